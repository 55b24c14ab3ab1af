// Invariant checkers for the stress matrix: each examines values (table
// texels, orders, lookups) and records how many it checked, how many broke
// the invariant and the worst offender. Every checker can fail: see
// tests/baker/invariants_test.cpp.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "baker/bake/bake.h"
#include "baker/stress/energy_budget.h"
#include "data_formats/spectra/spectrum.h"

namespace skybake {

struct InvariantResult {
  InvariantResult() = default;
  explicit InvariantResult(std::string invariant_name) : name(std::move(invariant_name)) {}

  std::string name;
  long long checked = 0;
  long long failed = 0;
  // How far the worst offender lies outside the invariant (in the units the
  // checker states; infinity for a NaN or an infinity), and where it is.
  double worst_excess = 0.0;
  std::string worst;

  bool passed() const { return failed == 0; }
  void pass() { ++checked; }
  void fail(double excess, const std::string& where);
};

// Transmittance may rise along a ray by this relative amount without failing:
// it is exp(-(tau(a) - tau(b))) of two interpolated float optical depths, and
// a depth of a few hundred (the thickest stress case) carries float rounding
// of ~1e-5 in the difference.
inline constexpr double kTransmittanceRiseTolerance = 1e-4;

// A view or sun direction change of this size (rad) is "small" for the
// continuity checks: well below a texel of any table at the stress sizes
// (the finest axis, mu near the horizon, is ~1e-3 rad per texel).
inline constexpr double kContinuityStep_rad = 1e-4;
// The largest relative change allowed for that step. Interpolation is linear
// between texels, so a 1e-4 rad step moves at most ~1/10 of a texel; a change
// above 5 % means a jump, not a slope, unless the step before changed nearly
// as much (kContinuitySlopeRatio).
inline constexpr double kContinuityMaxRelativeChange = 0.05;
// Where lookups integrate rather than interpolate (single scattering with the
// sun below the horizon) they follow the sky's own slope, which can be
// steeper than that: on the huge_planet case, at 440 nm from the top toward a
// sun 1.4 deg below the horizon, 6.5 % per step in the reference solver too.
// A slope changes about as much over the step before; a jump does not. A
// change above kContinuityMaxRelativeChange fails only if it is also more
// than this many times the change over the step before.
inline constexpr double kContinuitySlopeRatio = 2.0;
// Relative changes are taken against max(|a|, |b|, this share of the case's
// largest lookup). Near a zero the relative slope of a smooth quantity is
// unbounded: the ground seen where the sun is setting there (the disk's
// visible fraction times a vanishing cosine) changes by ~7 % per 1e-4 rad at
// 1e-3 of the brightest value. Compared against 1 % of the brightest value, a
// jump still fails once it exceeds 5e-4 of it.
inline constexpr double kContinuityFloorShare = 1e-2;

// In an atmosphere that does not absorb, (in - out - absorbed) / in may reach
// this per channel. The budget's own numerics are far below it: quadrature
// changes it by < 1e-4 when every node count is doubled, the orders after
// the last (tail estimate) by < 1e-4, the night side beyond the tables' sun
// range contributes < 4e-5 even taken at the clamped tables' upper bound, and
// the table-free reference solver's budget closes to 0.2 %. What remains is
// the bake's table interpolation: 1.16 % at the stress matrix's full sizes
// (440 nm, ground albedo 1), most of it from the mu_s axis
// (docs/STABILITY.md). A defect that loses or creates light in a stage, or a
// term missing from the budget, is several percent.
inline constexpr double kEnergyBudgetTolerance = 0.02;
// Doubling every node count of the budget's quadrature may change the
// imbalance by at most this; measured < 1e-4. Above it the integrals are not
// resolved and the imbalance says nothing about the bake.
inline constexpr double kEnergyBudgetQuadratureTolerance = 1e-3;

// Names the known-failure lists of stress_cases.cpp refer to.
inline const std::string kEnergyBudgetCloses = "energy budget closes";
inline const std::string kEnergyBudgetQuadratureConverged = "energy budget quadrature converged";

// |(in - out - absorbed) / in| <= tolerance in each channel; the excess is in
// units of the relative imbalance.
InvariantResult checkEnergyBudget(const EnergyBudget& budget, int channels, double tolerance);
// The imbalance with the default quadrature and with every node count
// doubled differ by at most kEnergyBudgetQuadratureTolerance.
InvariantResult checkEnergyBudgetQuadrature(const EnergyBudget& budget, const EnergyBudget& doubled, int channels);

// Every lane in [0, channels) finite and >= 0. `table` names the table in the
// worst-offender text; texels are indexed as stored.
InvariantResult checkFiniteNonNegativeTexels(const std::string& name, const std::vector<Spectrum>& texels,
                                             int channels);

// Each order's mean radiance below the previous one's, from order 3 on
// (order 2 may exceed order 1 where single scattering is weak); two orders
// that are both 0 (no scattering at all) pass.
InvariantResult checkOrdersDecrease(const std::vector<OrderContribution>& orders, int channels);

// Single values, accumulated into `result`; `where` describes the lookup.
void checkFiniteNonNegative(InvariantResult& result, const Spectrum& value, int channels, const std::string& where);
void checkUnitInterval(InvariantResult& result, const Spectrum& value, int channels, const std::string& where);
// Transmittance from a camera to points at increasing distance along one ray
// must not increase (beyond kTransmittanceRiseTolerance).
void checkNonIncreasing(InvariantResult& result, const std::vector<Spectrum>& along_ray, int channels,
                        const std::string& where);
// Two lookups a and b kContinuityStep_rad apart, `before` the same step
// before a: the relative change from a to b, relative to max(|a|, |b|,
// floor), at most kContinuityMaxRelativeChange, or at most
// kContinuitySlopeRatio times that from `before` to a.
void checkContinuous(InvariantResult& result, const Spectrum& before, const Spectrum& a, const Spectrum& b,
                     double floor, int channels, const std::string& where);

}  // namespace skybake
