#include "baker/stress/invariants.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace skybake {
namespace {

// A NaN or infinity is the worst possible offender.
double excessOf(double value, double bound_excess) {
  return std::isfinite(value) ? bound_excess : std::numeric_limits<double>::infinity();
}

}  // namespace

void InvariantResult::fail(double excess, const std::string& where) {
  ++checked;
  ++failed;
  if (std::isnan(excess)) excess = std::numeric_limits<double>::infinity();
  if (failed == 1 || excess > worst_excess) {
    worst_excess = excess;
    worst = where;
  }
}

void checkFiniteNonNegative(InvariantResult& result, const Spectrum& value, int channels, const std::string& where) {
  for (int c = 0; c < channels; ++c) {
    const double v = value[c];
    if (!std::isfinite(v) || v < 0.0) {
      result.fail(excessOf(v, -v), fmt::format("{} ch{} = {}", where, c, v));
      return;
    }
  }
  result.pass();
}

void checkUnitInterval(InvariantResult& result, const Spectrum& value, int channels, const std::string& where) {
  for (int c = 0; c < channels; ++c) {
    const double v = value[c];
    if (!(v >= 0.0 && v <= 1.0)) {
      result.fail(excessOf(v, v < 0.0 ? -v : v - 1.0), fmt::format("{} ch{} = {}", where, c, v));
      return;
    }
  }
  result.pass();
}

InvariantResult checkFiniteNonNegativeTexels(const std::string& name, const std::vector<Spectrum>& texels,
                                             int channels) {
  InvariantResult result{name};
  for (size_t i = 0; i < texels.size(); ++i) {
    const Spectrum& t = texels[i];
    bool ok = true;
    for (int c = 0; c < channels; ++c) ok = ok && std::isfinite(t[c]) && t[c] >= 0.0f;
    // Formatting the location only for offenders keeps the check fast.
    if (ok) {
      result.pass();
    } else {
      checkFiniteNonNegative(result, t, channels, fmt::format("texel {}", i));
    }
  }
  return result;
}

InvariantResult checkOrdersDecrease(const std::vector<OrderContribution>& orders, int channels) {
  InvariantResult result{"orders decrease"};  // the name stress_cases.cpp refers to
  for (size_t i = 2; i < orders.size(); ++i) {
    for (int c = 0; c < channels; ++c) {
      const double previous = orders[i - 1].mean_radiance[c];
      const double current = orders[i].mean_radiance[c];
      const bool both_zero = previous == 0.0 && current == 0.0;
      if (both_zero || current < previous) {
        result.pass();
      } else {
        result.fail(excessOf(current, previous > 0.0 ? current / previous - 1.0 : current),
                    fmt::format("order {} ch{}: {} after {}", orders[i].order, c, current, previous));
      }
    }
  }
  return result;
}

void checkNonIncreasing(InvariantResult& result, const std::vector<Spectrum>& along_ray, int channels,
                        const std::string& where) {
  for (size_t i = 1; i < along_ray.size(); ++i) {
    for (int c = 0; c < channels; ++c) {
      const double before = along_ray[i - 1][c];
      const double after = along_ray[i][c];
      if (!(after <= before * (1.0 + kTransmittanceRiseTolerance) + std::numeric_limits<float>::min())) {
        result.fail(excessOf(after, after - before),
                    fmt::format("{}, step {} ch{}: {} after {}", where, i, c, after, before));
        return;
      }
    }
  }
  result.pass();
}

void checkContinuous(InvariantResult& result, const Spectrum& before, const Spectrum& a, const Spectrum& b,
                     double floor, int channels, const std::string& where) {
  auto relativeChange = [floor](const Spectrum& x, const Spectrum& y, int c) {
    const double scale = std::max({std::abs(double(x[c])), std::abs(double(y[c])), floor});
    return std::abs(double(x[c]) - double(y[c])) / scale;
  };
  for (int c = 0; c < channels; ++c) {
    const double change = relativeChange(a, b, c);
    const bool slope = change <= kContinuitySlopeRatio * relativeChange(before, a, c);
    if (!(change <= kContinuityMaxRelativeChange || slope)) {
      result.fail(excessOf(change, change),
                  fmt::format("{} ch{}: {} -> {} ({:.1f} %)", where, c, a[c], b[c], 100.0 * change));
      return;
    }
  }
  result.pass();
}

InvariantResult checkEnergyBudget(const EnergyBudget& budget, int channels, double tolerance) {
  InvariantResult result{kEnergyBudgetCloses};
  const SpectrumD imbalance = budget.relativeImbalance();
  const SpectrumD out = budget.powerOut_W_per_nm();
  for (int c = 0; c < channels; ++c) {
    const double off = std::abs(imbalance[c]);
    if (off <= tolerance) {
      result.pass();
    } else {
      result.fail(excessOf(off, off - tolerance),
                  fmt::format("ch{}: in {:.4g} W/nm, out {:.4g}, absorbed {:.4g}: (in - out - absorbed) / in = "
                              "{:+.2f} % (tolerance {:.1f} %)",
                              c, budget.power_in_W_per_nm[c], out[c], budget.ground_absorbed_W_per_nm[c],
                              100.0 * imbalance[c], 100.0 * tolerance));
    }
  }
  return result;
}

InvariantResult checkEnergyBudgetQuadrature(const EnergyBudget& budget, const EnergyBudget& doubled, int channels) {
  InvariantResult result{kEnergyBudgetQuadratureConverged};
  const SpectrumD a = budget.relativeImbalance();
  const SpectrumD b = doubled.relativeImbalance();
  for (int c = 0; c < channels; ++c) {
    const double change = std::abs(a[c] - b[c]);
    if (change <= kEnergyBudgetQuadratureTolerance) {
      result.pass();
    } else {
      result.fail(excessOf(change, change - kEnergyBudgetQuadratureTolerance),
                  fmt::format("ch{}: imbalance {:+.3f} % with the default nodes, {:+.3f} % with twice as many", c,
                              100.0 * a[c], 100.0 * b[c]));
    }
  }
  return result;
}

}  // namespace skybake
