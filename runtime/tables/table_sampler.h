// Lookups in the baked tables: the one place that turns a geometric
// configuration into interpolated table values. The baker reads earlier
// scattering orders through these same functions, so bake and lookups share
// the parameterization exactly.
#pragma once

#include <cmath>
#include <vector>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/parameterization/texture_mapping.h"
#include "runtime/physics/night_sky.h"
#include "runtime/physics/phase_functions.h"
#include "runtime/physics/sun_disk.h"

namespace skybake {
namespace kernel {
#include "runtime/kernel/table_weights.glsl"
}  // namespace kernel
// The same kernel in float, for the blends of texels: the tables hold
// floats, and the shaders blend them in float too (a blend in double costs
// twilight lookups 5 %).
namespace kernel_float {
using Real = float;
using Real2 = glm::vec2;
using Real3 = glm::vec3;
#include "data_formats/kernel/kernel_builtins.inc"
#include "runtime/kernel/table_weights.glsl"
}  // namespace kernel_float

// Linear interpolation position on an axis of `size` texels whose centres sit
// at (i + 0.5) / size: the two neighbours and the weight of the upper one
// (the kernel runtime/kernel/table_weights.glsl's, the weight in float as the
// texels are).
struct AxisLerp {
  int i0;
  int i1;
  float w1;
  static AxisLerp of(const kernel::SkybakeAxisLerp& k) { return {k.i0, k.i1, static_cast<float>(k.w1)}; }
};

// The most by which the vertical optical depth above a point may differ
// from its geometric blend between the irradiance rows either side
// (TableSampler::irradiance, IrradianceRows::CosineOverDepth). Where the
// depth falls off exponentially the two are equal; the aerosol layer and the
// top bend it by a few percent between the default rows. A larger factor
// would come from a forged or broken optical-depth table and is not
// allowed to scale the sky's light without bound.
inline constexpr float kMaxIrradianceDepthFactor = 2.0f;

inline AxisLerp axisLerpFromTextureCoord(double u, int size) { return AxisLerp::of(kernel::skybakeAxisLerp(u, size)); }

// nu texels sit at i / (size - 1) in u_nu: both ends tabulated.
inline AxisLerp axisLerpNu(double u_nu, int size) { return AxisLerp::of(kernel::skybakeAxisLerpNu(u_nu, size)); }

// The same from the axes' interpolation weights, for callers that reuse one
// of them across lookups.
inline Spectrum sampleBilinear(const Texture2D& t, const AxisLerp& x, const AxisLerp& y) {
  const Spectrum a = t.at(x.i0, y.i0) + (t.at(x.i1, y.i0) - t.at(x.i0, y.i0)) * x.w1;
  const Spectrum b = t.at(x.i0, y.i1) + (t.at(x.i1, y.i1) - t.at(x.i0, y.i1)) * x.w1;
  return a + (b - a) * y.w1;
}

inline Spectrum sampleBilinear(const Texture2D& t, TextureCoord2D uv) {
  return sampleBilinear(t, axisLerpFromTextureCoord(uv.u, t.width), axisLerpFromTextureCoord(uv.v, t.height));
}

// How sample4D blends across mu_s and nu. With the sun below the horizon the
// sky dims by orders of magnitude per degree of sun depression, roughly
// exponentially, and toward or away from the sun by as much across one nu
// slice; a linear blend of two texels that far apart overestimates it (by
// tens of percent), a geometric one is exact for exponential falloff.
// Geometric blending costs a pow per channel, so it is used only there
// (twilight lookups): in daylight neighbours differ by little, the two blends
// agree to a fraction of a percent (measured: day errors unchanged), and the
// linear one keeps lookups vectorized.
enum class Blend { Linear, GeometricWhereSteep };

// Where the blend starts to be geometric and where it is wholly so: the
// kernel's SKYBAKE_GEOMETRIC_BLEND_RATIO and SKYBAKE_FULLY_GEOMETRIC_BLEND_RATIO
// (skybakeGeometricBlendShare says why two).
inline float geometricBlend(float a, float b, float w) { return kernel_float::skybakeGeometricBlend(a, b, w); }

inline Spectrum blendGeometricWhereSteep(const Spectrum& a, const Spectrum& b, float w) {
  Spectrum out;
  for (int c = 0; c < Spectrum::length(); ++c) {
    out[c] = kernel_float::skybakeBlendGeometricWhereSteep(a[c], b[c], w);
  }
  return out;
}

template <Blend blend>
inline Spectrum blendAcross(const Spectrum& a, const Spectrum& b, float w) {
  if constexpr (blend == Blend::Linear)
    return a + (b - a) * w;
  else
    return blendGeometricWhereSteep(a, b, w);
}

inline Spectrum blendAcross(const Spectrum& a, const Spectrum& b, float w, Blend blend) {
  return blend == Blend::Linear ? blendAcross<Blend::Linear>(a, b, w)
                                : blendAcross<Blend::GeometricWhereSteep>(a, b, w);
}

// The blend for a radiance lookup with the sun at zenith cosine mu_s.
inline Blend radianceBlend(double mu_s) { return mu_s < 0.0 ? Blend::GeometricWhereSteep : Blend::Linear; }

// One nu slice of a quadrilinear lookup: trilinear in (mu_s, mu, r), mu_s
// blended as `blend` says. Callers that look up many nu at one (r, mu, mu_s)
// interpolate every slice once and blend across nu themselves.
template <Blend blend = Blend::Linear>
inline Spectrum sampleNuSlice(const Texture4D& t, const AxisLerp& r, const AxisLerp& mu, const AxisLerp& mu_s,
                              int i_nu) {
  auto row = [&](int i_r, int i_mu) {
    return blendAcross<blend>(t.at(i_r, i_mu, mu_s.i0, i_nu), t.at(i_r, i_mu, mu_s.i1, i_nu), mu_s.w1);
  };
  const Spectrum r0 = row(r.i0, mu.i0) + (row(r.i0, mu.i1) - row(r.i0, mu.i0)) * mu.w1;
  const Spectrum r1 = row(r.i1, mu.i0) + (row(r.i1, mu.i1) - row(r.i1, mu.i0)) * mu.w1;
  return r0 + (r1 - r0) * r.w1;
}

// Quadrilinear lookup: trilinear in (mu_s, mu, r) within the two nearest nu
// slices, then across nu; mu_s and nu blended as `blend` says (a template
// argument, so the bake's linear lookups carry no branch).
// The same from the four axes' interpolation weights, for callers that reuse
// some of them across lookups.
template <Blend blend = Blend::Linear>
inline Spectrum sample4D(const Texture4D& t, const AxisLerp& r, const AxisLerp& mu, const AxisLerp& mu_s,
                         const AxisLerp& nu) {
  return blendAcross<blend>(sampleNuSlice<blend>(t, r, mu, mu_s, nu.i0), sampleNuSlice<blend>(t, r, mu, mu_s, nu.i1),
                            nu.w1);
}

// sample4D of a table with a single r and a single mu_s texel (a 4D table
// already interpolated at one (r, mu_s), Sky::skyRadianceBatch), without the
// work the two trivial axes would cost: the same result, since blends with
// weight 0 between a texel and itself return it exactly (tests tie the two).
template <Blend blend = Blend::Linear>
inline Spectrum sampleMuNuSlice(const Texture4D& slice, const AxisLerp& mu, const AxisLerp& nu) {
  auto at = [&](int i_mu, int i_nu) -> const Spectrum& { return slice.at(0, i_mu, 0, i_nu); };
  auto lerp_mu = [&](int i_nu) { return at(mu.i0, i_nu) + (at(mu.i1, i_nu) - at(mu.i0, i_nu)) * mu.w1; };
  return blendAcross<blend>(lerp_mu(nu.i0), lerp_mu(nu.i1), nu.w1);
}

template <Blend blend = Blend::Linear>
inline Spectrum sample4D(const Texture4D& t, const ScatteringCoord& c, const AxisLerp& nu) {
  return sample4D<blend>(t, axisLerpFromTextureCoord(c.u_r, t.r_size), axisLerpFromTextureCoord(c.u_mu, t.mu_size),
                         axisLerpFromTextureCoord(c.u_mu_s, t.mu_s_size), nu);
}

// The same with the blend chosen at run time (see radianceBlend).
inline Spectrum sample4D(const Texture4D& t, const ScatteringCoord& c, const AxisLerp& nu, Blend blend) {
  return blend == Blend::Linear ? sample4D<Blend::Linear>(t, c, nu) : sample4D<Blend::GeometricWhereSteep>(t, c, nu);
}

class TableSampler {
 public:
  // `night`: how the tables go on below their lowest sun (runtime/physics/night_sky.h);
  // by default they do not (the bake reads them only inside its domain).
  TableSampler(const AtmosphereDomain& domain, const TextureSizes& sizes, const NightContinuation& night = {})
      : domain_(domain),
        sizes_(sizes),
        scattering_sizes_(ScatteringSizes::fromTextureSizes(sizes)),
        H_(domain.horizonToTopDistance()),
        night_(night),
        night_4d_(domain.scattering_mu_s_coord_min <= 0.0),
        irradiance_horizon_units_(irradianceHorizonUnits(domain, sizes)) {}

  const AtmosphereDomain& domain() const { return domain_; }
  const NightContinuation& night() const { return night_; }
  // The night continuation's scale for the irradiance table, which covers
  // every sun down to the domain's lowest, and for the 4D tables, whose
  // sun axis reaches it unless a [scene] narrows it (they are clamped to
  // the scene's lowest sun then, as documented in runtime/sky.h).
  Spectrum nightScale(double mu_s) const { return night_.scale(mu_s); }
  Spectrum nightScale4D(double mu_s) const { return night_4d_ ? night_.scale(mu_s) : Spectrum(1.0f); }
  const TextureSizes& sizes() const { return sizes_; }
  const ScatteringSizes& scatteringSizes() const { return scattering_sizes_; }

  // Optical depth from (r, mu) to the top boundary (the ground ignored).
  // Optical depth from (r, mu) to the top boundary (the ground ignored).
  Spectrum opticalDepthToTop(const Texture2D& optical_depth, double r, double mu) const {
    return OpticalDepthFromR(*this, r).toTop(optical_depth, mu);
  }

  // Optical depth over the segment [0, d] of the ray (r, mu). Written as a
  // difference of optical depths to the top rather than a ratio of
  // transmittances, so it stays exact where transmittances underflow. For a
  // ray that hits the ground both legs are taken reversed (pointing up),
  // where the table is defined. So is a segment of a downward ray that ends
  // before the ray's lowest point: forward, both depths would run through
  // the densest air at that point (thousands in a thick haze), and the
  // table's relative error on them would swamp their small difference.
  Spectrum opticalDepthAlongRay(const Texture2D& optical_depth, double r, double mu, double d,
                                bool ray_intersects_ground) const {
    const double r_d = radiusInDomain(r, mu, d);
    const RayLeg leg = RayLeg::to(r, mu, d, r_d, ray_intersects_ground);
    const Spectrum from_start = opticalDepthToTop(optical_depth, r, leg.reversed ? -mu : mu);
    return leg.depth(optical_depth, from_start, OpticalDepthFromR(*this, r_d));
  }
  // The optical depth between two points on one ray from the depths to the
  // top at the nearer (`from_nearer`) and the farther point, as seen looking
  // away from the top; interpolation may leave a tiny negative, read as 0.
  static Spectrum depthBetween(const Spectrum& from_nearer, const Spectrum& from_farther) {
    return glm::max(from_nearer - from_farther, Spectrum(0.0f));
  }

  // Transmittance to the sun from radius r with sun zenith cosine mu_s,
  // including the part of the sun disk above the horizon (linear ramp over the
  // disk's angular diameter).
  Spectrum transmittanceToSun(const Texture2D& optical_depth, double r, double mu_s, double sun_angular_radius) const {
    const SunFromR sun(*this, r, sun_angular_radius);
    const double visible = sun.visibleFraction(mu_s);
    if (visible <= 0.0) return Spectrum(0.0f);
    return glm::exp(-sun.opticalDepth(optical_depth, sun.muCoord(mu_s))) * static_cast<float>(visible);
  }

  // Optical depths to the top from one r: where a direction falls on the
  // table's mu axis (selects only, so loops over many directions vectorize)
  // and the table read, with the r coordinate worked out once.
  class OpticalDepthFromR {
   public:
    OpticalDepthFromR(const TableSampler& sampler, double r)
        : rho_(sampler.domain_.distanceToHorizon(r)),
          mu_coord_(TransmittanceMuCoordAtR::of(sampler.domain_, sampler.sizes_.transmittance_mu, r, rho_, sampler.H_)),
          r_lerp_(axisLerpFromTextureCoord(textureCoordFromUnitRange(rho_ / sampler.H_, sampler.sizes_.transmittance_r),
                                           sampler.sizes_.transmittance_r)) {}
    double muCoord(double mu) const { return mu_coord_(mu); }
    double muCoordAtDistance(double dist_to_top_m) const { return mu_coord_.atDistance(dist_to_top_m); }
    // Optical depth to the top at the mu coordinate `u_mu`.
    Spectrum opticalDepth(const Texture2D& optical_depth, double u_mu) const {
      return sampleBilinear(optical_depth, axisLerpFromTextureCoord(u_mu, optical_depth.width), r_lerp_);
    }
    Spectrum toTop(const Texture2D& optical_depth, double mu) const { return opticalDepth(optical_depth, muCoord(mu)); }

   private:
    double rho_;  // distanceToHorizon(r)
    TransmittanceMuCoordAtR mu_coord_;
    AxisLerp r_lerp_;  // the r axis, the same for every direction
  };

  // The leg of a ray (r, mu) from its start to distance d (radius r_d):
  // the point's zenith cosine there, and whether both depths are taken
  // reversed, pointing up (opticalDepthAlongRay says when).
  struct RayLeg {
    bool reversed;
    double mu_d;
    static RayLeg to(double r, double mu, double d, double r_d, bool ray_intersects_ground) {
      return {ray_intersects_ground || d <= -r * mu, cosineAlongRay(r, mu, d, r_d)};
    }
    // The depth along the leg from the start's depth to the top (along -mu
    // when reversed, else mu) and the point's, read at r_d through at_d.
    Spectrum depth(const Texture2D& optical_depth, const Spectrum& from_start, const OpticalDepthFromR& at_d) const {
      return reversed ? depthBetween(at_d.toTop(optical_depth, -mu_d), from_start)
                      : depthBetween(from_start, at_d.toTop(optical_depth, mu_d));
    }
  };

  // How much of the sun's disk is above the horizon from radius r, for a sun
  // at zenith cosine mu_s (linear ramp over the disk's angular diameter):
  // cheap, so a point in the planet's shadow is known before any table read.
  class SunDiskAtR {
   public:
    SunDiskAtR(const TableSampler& sampler, double r, double sun_angular_radius)
        : tangent_mu_(tangentZenithCosine(r, sampler.domain_.bottom_radius_m)),
          disk_half_size_(sunDiskHalfSizeAtHorizon(sampler.domain_.bottom_radius_m, r, sun_angular_radius)) {}
    double visibleFraction(double mu_s) const { return sunDiskVisibleFraction(mu_s - tangent_mu_, disk_half_size_); }

   private:
    double tangent_mu_, disk_half_size_;
  };

  // transmittanceToSun's steps for many suns seen from one r: the
  // branch-free part (where on the table's mu axis, how much of the disk is
  // up) for all suns in a loop that vectorizes, then the table reads.
  class SunFromR : public OpticalDepthFromR {
   public:
    SunFromR(const TableSampler& sampler, double r, double sun_angular_radius)
        : OpticalDepthFromR(sampler, r), disk_(sampler, r, sun_angular_radius) {}
    double visibleFraction(double mu_s) const { return disk_.visibleFraction(mu_s); }

   private:
    SunDiskAtR disk_;
  };

  // The optical depths of many points of one ray (r, mu) from its start,
  // each as opticalDepthAlongRay gives it: the start's depths to the top
  // (both ways) read once, and each point's through an OpticalDepthFromR at
  // its radius, which the caller may share with that point's sunlight.
  class DepthAlongRay {
   public:
    DepthAlongRay(const TableSampler& sampler, const Texture2D& optical_depth, double r, double mu,
                  bool ray_intersects_ground)
        : sampler_(sampler),
          optical_depth_(optical_depth),
          r_(r),
          mu_(mu),
          ray_intersects_ground_(ray_intersects_ground),
          forward_(sampler.opticalDepthToTop(optical_depth, r, mu)),
          reversed_(sampler.opticalDepthToTop(optical_depth, r, -mu)) {}
    // opticalDepthAlongRay(optical_depth, r, mu, d, ray_intersects_ground),
    // reading the point's depth through `at_r`, built at radius r_point,
    // where r_point is where opticalDepthAlongRay places the point (the
    // caller's own radius of it, unless the domain's radii differ from those
    // it clamps to).
    Spectrum to(double d, double r_point, const OpticalDepthFromR& at_r) const {
      const double r_d = sampler_.radiusInDomain(r_, mu_, d);
      const RayLeg leg = RayLeg::to(r_, mu_, d, r_d, ray_intersects_ground_);
      const Spectrum& from_start = leg.reversed ? reversed_ : forward_;
      return r_d == r_point ? leg.depth(optical_depth_, from_start, at_r)
                            : leg.depth(optical_depth_, from_start, OpticalDepthFromR(sampler_, r_d));
    }

   private:
    const TableSampler& sampler_;
    const Texture2D& optical_depth_;
    double r_, mu_;
    bool ray_intersects_ground_;
    Spectrum forward_, reversed_;  // to the top from the start, along mu and along -mu
  };

  ScatteringCoord scatteringCoord(double r, double mu, double mu_s, double nu, bool ray_intersects_ground) const {
    return scatteringCoordFromRMuMuSNu(domain_, scattering_sizes_, r, mu, mu_s, nu, ray_intersects_ground);
  }

  Spectrum scattering(const Texture4D& table, double r, double mu, double mu_s, double nu,
                      bool ray_intersects_ground) const {
    const ScatteringCoord c = scatteringCoord(r, mu, mu_s, nu, ray_intersects_ground);
    return sample4D(table, c, axisLerpNu(c.u_nu, table.nu_size), radianceBlend(mu_s)) * nightScale4D(mu_s);
  }

  // The multiple-scattering density table (linear mu, see densityCoordMu);
  // its sun texels blended as a radiance lookup's (it falls as steeply with
  // a setting sun).
  Spectrum multipleDensity(const Texture4D& table, double r, double mu, double mu_s, double nu) const {
    ScatteringCoord c = scatteringCoord(r, 1.0, mu_s, nu, false);
    c.u_mu = densityCoordMu(mu, table.mu_size);
    return sample4D(table, c, axisLerpNu(c.u_nu, table.nu_size), radianceBlend(mu_s)) * nightScale4D(mu_s);
  }

  // Sky irradiance on a horizontal surface at radius r.
  // Across mu_s: linear with the sun above the ground's horizon. Below it,
  // where the irradiance falls about tenfold per degree of depression,
  // geometric (both neighbours positive): linear read up to 6 % high between
  // texels 0.5 deg apart in twilight, geometric within 0.5 %
  // (docs/MEASUREMENTS.md). The interval holding the horizon takes the
  // geometric blend in proportion to its part below it, so the lookup is
  // continuous for any table size. With IrradianceRows::CosineOverDepth
  // each row's sun axis is relative to its own horizon
  // (skybakeIrradianceSunCosine), so that every row's own sunset falls on
  // one texel, and the ground's horizon sits higher on a higher row's axis.
  // Across r: the irradiance over the vertical optical depth above (of
  // domain_.irradiance_depth_channel) geometrically, times the depth above
  // r (with IrradianceRows::Linear, the irradiance alone): exact where the
  // sky glows in proportion to the air above it, toward the top and wherever
  // both fall off alike, and it follows the aerosol layer; linear where a
  // neighbour is 0 (night). On rows linear in altitude the irradiance alone
  // read 6 % low midway between rows 4 km apart below the top, and 4 % high
  // 2 km up at 680 nm (docs/MEASUREMENTS.md, "The sky irradiance across
  // altitude"). Between the last row below the top and the top, where the
  // sky above thins to nothing and the top row holds 0, the lower row's
  // irradiance scaled by the vertical optical depth above r over that above
  // the row, per channel: a thin layer's sky glows in proportion to the air
  // in it.
  Spectrum irradiance(const Texture2D& irradiance, const Texture2D& optical_depth, double r, double mu_s) const {
    const TextureCoord2D uv = irradianceCoordFromRMuS(domain_, sizes_.irradiance_mu_s, sizes_.irradiance_r, r, mu_s);
    const AxisLerp x = axisLerpFromTextureCoord(uv.u, irradiance.width);
    const AxisLerp y = axisLerpFromTextureCoord(uv.v, irradiance.height);
    const Spectrum low = irradianceRow(irradiance, x, y.i0);
    if (y.i1 == irradiance.height - 1 && y.i1 > y.i0) {
      const double row_r = irradianceTexelConfig(domain_, irradiance.width, irradiance.height, 0, y.i0).r;
      return low * thinningToTop(optical_depth, r, row_r) * nightScale(mu_s);
    }
    const Spectrum high = irradianceRow(irradiance, x, y.i1);
    Spectrum out;
    for (int c = 0; c < kMaxChannels; ++c) {
      out[c] = kernel_float::skybakeBlendGeometricWherePositive(low[c], high[c], y.w1, 1.0f);
    }
    if (domain_.irradiance_rows == IrradianceRows::CosineOverDepth && y.i1 > y.i0) {
      out *= depthOverItsBlend(optical_depth, r, irradiance.height, y);
    }
    return out * nightScale(mu_s);
  }
  // The sky irradiance on the ground (the table's lowest row), blended
  // across mu_s as irradiance() does.
  Spectrum groundIrradiance(const Texture2D& irradiance, double mu_s) const {
    const TextureCoord2D uv =
        irradianceCoordFromRMuS(domain_, sizes_.irradiance_mu_s, sizes_.irradiance_r, domain_.bottom_radius_m, mu_s);
    return irradianceRow(irradiance, axisLerpFromTextureCoord(uv.u, irradiance.width), 0) * nightScale(mu_s);
  }

 private:
  // The radius of the point at distance d along the ray (r, mu), kept in the
  // domain's shell against rounding (opticalDepthAlongRay, DepthAlongRay).
  double radiusInDomain(double r, double mu, double d) const {
    return std::clamp(radiusAlongRay(r, mu, d), domain_.bottom_radius_m, domain_.top_radius_m);
  }

  // Each irradiance row's unit sun coordinate of the ground's horizon
  // (mu_s = 0): below it the sky's light falls steepest, in the planet's
  // shadow or, higher up, in the sunlight's grazing path. With rows on
  // their own horizons (IrradianceRows::CosineOverDepth) it moves up the
  // axis with the row's altitude.
  static std::vector<double> irradianceHorizonUnits(const AtmosphereDomain& domain, const TextureSizes& sizes) {
    std::vector<double> units(static_cast<size_t>(std::max(sizes.irradiance_r, 0)));
    const int cosine_rows = domain.irradianceCosineRows();
    for (int i_r = 0; i_r < sizes.irradiance_r; ++i_r) {
      const double r = kernel::skybakeIrradianceRowRadius(i_r, sizes.irradiance_r, domain.bottom_radius_m,
                                                          domain.top_radius_m, cosine_rows);
      units[i_r] = muSUnitCoord(
          domain, kernel::skybakeIrradianceSunCosine(0.0, r, domain.bottom_radius_m, domain.mu_s_min, cosine_rows));
    }
    return units;
  }

  // Row i_r of the irradiance table at the mu_s position x (see irradiance).
  Spectrum irradianceRow(const Texture2D& irradiance, const AxisLerp& x, int i_r) const {
    const Spectrum a = irradiance.at(x.i0, i_r), b = irradiance.at(x.i1, i_r);
    const double below_horizon =
        kernel::skybakeBelowHorizonShare(irradiance_horizon_units_[i_r] * (irradiance.width - 1), x.i1);
    // Above the horizon the linear blend alone, in float (vectorized).
    if (below_horizon <= 0.0) return a + (b - a) * x.w1;
    Spectrum out;
    for (int c = 0; c < kMaxChannels; ++c) {
      out[c] = kernel_float::skybakeBlendGeometricWherePositive(a[c], b[c], x.w1, static_cast<float>(below_horizon));
    }
    return out;
  }
  // The vertical optical depth above r over its geometric blend between the
  // rows y.i0 and y.i1 (below the top), in the depth channel: what turns the
  // irradiance's geometric blend into that of the irradiance over the depth
  // (irradiance). 1 where a row has no air above it; within
  // [1 / kMaxIrradianceDepthFactor, kMaxIrradianceDepthFactor].
  float depthOverItsBlend(const Texture2D& optical_depth, double r, int rows, const AxisLerp& y) const {
    const int cosine = 1;
    const int k = domain_.irradiance_depth_channel;
    const double r_low =
        kernel::skybakeIrradianceRowRadius(y.i0, rows, domain_.bottom_radius_m, domain_.top_radius_m, cosine);
    const double r_high =
        kernel::skybakeIrradianceRowRadius(y.i1, rows, domain_.bottom_radius_m, domain_.top_radius_m, cosine);
    const float low = opticalDepthToTop(optical_depth, r_low, 1.0)[k];
    const float high = opticalDepthToTop(optical_depth, r_high, 1.0)[k];
    const float here = opticalDepthToTop(optical_depth, std::clamp(r, r_low, r_high), 1.0)[k];
    if (!(low > 0.0f && high > 0.0f && here > 0.0f)) return 1.0f;
    const float blend = std::exp((1.0f - y.w1) * std::log(low) + y.w1 * std::log(high));
    return std::clamp(here / blend, 1.0f / kMaxIrradianceDepthFactor, kMaxIrradianceDepthFactor);
  }
  // The vertical optical depth above r over that above r_row (r_row < top),
  // per channel: 1 at r_row, 0 at the top. Kept within [0, 1] against the
  // table's interpolation; 1 where no air is above r_row.
  Spectrum thinningToTop(const Texture2D& optical_depth, double r, double r_row) const {
    const Spectrum above_r = opticalDepthToTop(optical_depth, std::min(r, domain_.top_radius_m), 1.0);
    const Spectrum above_row = opticalDepthToTop(optical_depth, r_row, 1.0);
    Spectrum ratio(1.0f);
    for (int c = 0; c < kMaxChannels; ++c) {
      if (above_row[c] > 0.0f) ratio[c] = std::clamp(above_r[c] / above_row[c], 0.0f, 1.0f);
    }
    return ratio;
  }

  AtmosphereDomain domain_;
  TextureSizes sizes_;
  ScatteringSizes scattering_sizes_;
  double H_;  // domain_.horizonToTopDistance()
  NightContinuation night_;
  bool night_4d_;                                 // the 4D tables' sun axis reaches the domain's lowest sun
  std::vector<double> irradiance_horizon_units_;  // irradianceHorizonUnits
};

}  // namespace skybake
