// Scattering density J(x, w) = integral over incident directions w_i of
// (beta_R(x) P_R(w . w_i) + beta_M(x) P_M(w . w_i)) L(x, w_i) dw_i.
//
// For a fixed texel row (r, mu_s), the incident radiance L(x, w_i) on a fixed
// set of directions in a frame tied to the zenith and the sun does not depend
// on the view direction w. It is evaluated once per (r, mu_s), one
// interpolation of the previous order's tables per zenith ring, and turned
// into cosine modes of the azimuth per ring; the sum over directions toward
// each view zenith is then a product of those modes with the phase functions'
// (scattering_density_kernel.h), and each texel's nu only picks the azimuth
// at which the modes are summed.
#include <omp.h>

#include <array>
#include <vector>

#include "baker/stages/scattering_density_kernel.h"
#include "baker/stages/scattering_density_table.h"
#include "runtime/physics/atmosphere_media.h"

namespace skybake {
namespace {

// Light of order n arriving on a ring of incident directions, as cosine modes
// of the azimuth from the sun: per node, channel and mode, each direction's
// radiance times its solid angle.
struct RingModes {
  std::array<std::array<std::array<float, kAzimuthModes>, kMaxChannels>, kDensityZenithNodes> value;
};

// cos(m phi_j) for the midpoint azimuths phi_j = (j + 1/2) 2 pi / N of half
// the ring; the incident radiance is even in phi (the sun lies in the x-z
// plane), so the other half mirrors it and doubles each mode.
struct RingCosines {
  std::array<std::array<float, kAzimuthModes>, kDensityAzimuths / 2> value;
  std::array<double, kDensityAzimuths / 2> cos_phi;
  RingCosines() {
    for (int j = 0; j < kDensityAzimuths / 2; ++j) {
      const double phi = (j + 0.5) * 2.0 * kPi / kDensityAzimuths;
      cos_phi[j] = std::cos(phi);
      for (int m = 0; m < kAzimuthModes; ++m) value[j][m] = static_cast<float>(2.0 * std::cos(m * phi));
    }
  }
};

void incidentRingModes(const StageContext& ctx, const DensityKernelAltitude& kernel, OrderRadianceAlongNu& previous,
                       const Texture2D& ground_irradiance, double r, double mu_s, RingModes& out) {
  static const RingCosines cosines;
  const AtmosphereParameters& a = ctx.atmosphere;
  const double sun_x = safeSqrt(1.0 - mu_s * mu_s);
  const Spectrum ground_brdf = a.ground_albedo * static_cast<float>(1.0 / kPi);
  for (int i = 0; i < kDensityZenithNodes; ++i) {
    const IncidentZenithNode& node = kernel.nodes[i];
    previous.moveTo(r, node.cos_theta, mu_s, node.hits_ground);
    auto& modes = out.value[i];
    for (auto& channel : modes) channel.fill(0.0f);
    for (int j = 0; j < kDensityAzimuths / 2; ++j) {
      const double sun_side = node.sin_theta * cosines.cos_phi[j] * sun_x;  // direction's x times the sun's
      Spectrum radiance = previous.at(clampCosine(sun_side + node.cos_theta * mu_s));
      if (node.hits_ground) {
        // Light of order n - 1 reflected by the Lambertian ground, seen
        // through the air between the ground point and x.
        const double ground_mu_s =
            clampCosine(node.ground_up_horizontal * cosines.cos_phi[j] * sun_x + node.ground_up_vertical * mu_s);
        radiance +=
            node.ground_transmittance * ground_brdf * ctx.sampler.groundIrradiance(ground_irradiance, ground_mu_s);
      }
      for (int c = 0; c < kMaxChannels; ++c) {
        const float weighted = static_cast<float>(radiance[c] * node.solid_angle_sr);
#pragma omp simd
        for (int m = 0; m < kAzimuthModes; ++m) modes[c][m] += weighted * cosines.value[j][m];
      }
    }
  }
}

// The phase-weighted sums over all incident directions toward one view zenith,
// as cosine modes of the view's azimuth from the sun.
struct ViewModes {
  std::array<std::array<float, kRayleighAzimuthModes>, kMaxChannels> rayleigh;
  std::array<std::array<float, kAzimuthModes>, kMaxChannels> mie;
};

ViewModes viewModes(const DensityKernelAltitude& kernel, const RingModes& ring, int i_mu) {
  ViewModes v{};
  for (int i = 0; i < kDensityZenithNodes; ++i) {
    const size_t pair = static_cast<size_t>(i_mu) * kDensityZenithNodes + i;
    const float* rayleigh = &kernel.rayleigh_modes[pair * kRayleighAzimuthModes];
    const float* mie = &kernel.mie_modes[pair * kAzimuthModes];
    for (int c = 0; c < kMaxChannels; ++c) {
      const float* incident = ring.value[i][c].data();
      for (int m = 0; m < kRayleighAzimuthModes; ++m) v.rayleigh[c][m] += rayleigh[m] * incident[m];
      float* sum = v.mie[c].data();
#pragma omp simd
      for (int m = 0; m < kAzimuthModes; ++m) sum[m] += mie[m] * incident[m];
    }
  }
  return v;
}

// sum_m modes[m] cos(m phi), from cos(phi) by the Chebyshev recurrence
// cos(m phi) = 2 cos(phi) cos((m - 1) phi) - cos((m - 2) phi).
template <size_t N>
Spectrum sumOfModes(const std::array<std::array<float, N>, kMaxChannels>& modes,
                    const std::array<float, kAzimuthModes>& cos_m_phi) {
  Spectrum out(0.0f);
  for (int c = 0; c < kMaxChannels; ++c) {
    float sum = 0.0f;
#pragma omp simd reduction(+ : sum)
    for (size_t m = 0; m < N; ++m) sum += modes[c][m] * cos_m_phi[m];
    out[c] = sum;
  }
  return out;
}

std::array<float, kAzimuthModes> cosinesOfMultiples(double cos_phi) {
  std::array<float, kAzimuthModes> out{};
  double previous = 1.0, current = cos_phi;
  out[0] = 1.0f;
  for (int m = 1; m < kAzimuthModes; ++m) {
    out[m] = static_cast<float>(current);
    const double next = 2.0 * cos_phi * current - previous;
    previous = current;
    current = next;
  }
  return out;
}

}  // namespace

Texture4D computeScatteringDensityTable(const StageContext& ctx, const ScatteringDensityKernel& kernel,
                                        const OrderRadiance& previous, const TableSampler& previous_sampler,
                                        const MultipleScatteringPhase& shape, const Texture2D& ground_irradiance) {
  const AtmosphereParameters& a = ctx.atmosphere;
  const ScatteringSizes& s = ctx.sampler.scatteringSizes();
  const AtmosphereMedia media(a);
  Texture4D out(s.r, s.mu, s.mu_s, s.nu);
  // The kernel's phase modes are the shapes; their normalisations go here.
  const float cs_norm = static_cast<float>(CornetteShanksPhase(a.mie_phase_g).normalisation());
  const float rayleigh_norm = static_cast<float>(kRayleighPhaseNormalisation);

#pragma omp parallel
  {
    // Linear across nu: see NuBlend.
    OrderRadianceAlongNu incident(previous, previous_sampler, a.mie_phase_g, NuBlend::Linear);
    RingModes ring;
#pragma omp for collapse(2) schedule(dynamic)
    for (int i_r = 0; i_r < s.r; ++i_r) {
      for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) {
        const double r = rFromScatteringTexel(ctx.sampler.domain(), s, i_r);
        const double mu_s = muSFromScatteringTexel(ctx.sampler.domain(), s, i_mu_s);
        const DensityKernelAltitude& at_r = kernel.altitudes[i_r];
        incidentRingModes(ctx, at_r, incident, ground_irradiance, r, mu_s, ring);
        const double altitude = r - a.bottom_radius_m;
        const Spectrum rayleigh_coefficient =
            a.rayleigh_scattering * (rayleigh_norm * static_cast<float>(media.rayleighDensity(altitude)));
        const Spectrum mie_coefficient = a.mie_scattering * (cs_norm * static_cast<float>(media.mieDensity(altitude)));
        const double sun_x = safeSqrt(1.0 - mu_s * mu_s);
        const SpectrumD peak_weight = shape.peakWeightAt(altitude);

        for (int i_mu = 0; i_mu < s.mu; ++i_mu) {
          const double density_mu = muFromDensityTexel(i_mu, s.mu);
          const double view_sin = safeSqrt(1.0 - density_mu * density_mu);
          const ViewModes modes = viewModes(at_r, ring, i_mu);
          // Slices past the end of the nu range this (mu, mu_s) allows are
          // clamped to it and repeat the last value (every slice does at
          // mu = -1 and 1): computed once.
          double last_nu = 2.0;  // no nu
          Spectrum last_value(0.0f);
          for (int i_nu = 0; i_nu < s.nu; ++i_nu) {
            const double nu = clampNu(nuOfScatteringSlice(i_nu, s.nu), density_mu, mu_s);
            if (nu != last_nu) {
              // The view's azimuth from the sun: its x component over its
              // horizontal length (any azimuth where either is vertical: all
              // modes above 0 vanish there).
              const double view_x = sun_x > 0.0 ? (nu - density_mu * mu_s) / sun_x : 0.0;
              const double cos_phi = view_sin > 0.0 ? clampCosine(view_x / view_sin) : 1.0;
              const std::array<float, kAzimuthModes> cos_m_phi = cosinesOfMultiples(cos_phi);
              const Spectrum density = rayleigh_coefficient * sumOfModes(modes.rayleigh, cos_m_phi) +
                                       mie_coefficient * sumOfModes(modes.mie, cos_m_phi);
              last_value = density / shape(peak_weight, nu);
              last_nu = nu;
            }
            out.at(i_r, i_mu, i_mu_s, i_nu) = last_value;
          }
        }
        ctx.progress.advance(1);
      }
    }
  }
  return out;
}

}  // namespace skybake
