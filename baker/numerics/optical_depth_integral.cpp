#include "baker/numerics/optical_depth_integral.h"

#include <algorithm>
#include <vector>

#include "data_formats/parameterization/ray_sphere.h"
#include "runtime/physics/ray_quadrature.h"

namespace skybake {
namespace {

// Altitudes where a profile's density has a kink.
void appendKinkAltitudes(const DensityProfile& profile, std::vector<double>& altitudes) {
  double layer_bottom = 0.0;
  for (size_t i = 0; i < profile.size(); ++i) {
    const DensityLayer& l = profile[i];
    const bool last = i + 1 == profile.size();
    const double layer_top = last ? 1e300 : layer_bottom + l.width_m;
    if (!last) altitudes.push_back(layer_top);
    if (l.exp_term == 0.0 && l.linear_term != 0.0) {
      for (double level : {0.0, 1.0}) {  // where the clamp to [0, 1] starts
        const double h = (level - l.constant_term) / l.linear_term;
        if (h > layer_bottom && h < layer_top) altitudes.push_back(h);
      }
    }
    layer_bottom = layer_top;
  }
}

}  // namespace

SpectrumD integrateOpticalDepthAlongRay(const AtmosphereMedia& media, double r, double mu, double length_m,
                                        int segments_per_piece) {
  const AtmosphereParameters& a = media.parameters();
  // Reused per thread: this runs millions of times in the reference solver.
  thread_local std::vector<double> kinks, breaks;
  kinks.clear();
  appendKinkAltitudes(a.rayleigh_density, kinks);
  appendKinkAltitudes(a.mie_density, kinks);
  appendKinkAltitudes(a.absorption_density, kinks);

  breaks.assign({0.0, length_m});
  for (double h : kinks) {
    const double radius = a.bottom_radius_m + h;
    const double discriminant = r * r * (mu * mu - 1.0) + radius * radius;
    if (discriminant < 0.0) continue;
    for (double t : {-r * mu - std::sqrt(discriminant), -r * mu + std::sqrt(discriminant)}) {
      if (t > 0.0 && t < length_m) breaks.push_back(t);
    }
  }
  std::sort(breaks.begin(), breaks.end());

  SpectrumD depth(0.0);
  for (size_t p = 0; p + 1 < breaks.size(); ++p) {
    if (breaks[p + 1] <= breaks[p]) continue;
    forEachQuadratureNode(breaks[p], breaks[p + 1], segments_per_piece, [&](double t, double w) {
      const double altitude = radiusAlongRay(r, mu, t) - a.bottom_radius_m;
      depth += media.extinction(altitude) * w;
    });
  }
  return depth;
}

SpectrumD integrateOpticalDepthToTop(const AtmosphereMedia& media, double r, double mu, int segments_per_piece) {
  return integrateOpticalDepthAlongRay(media, r, mu, distanceToOuterSphere(r, mu, media.parameters().top_radius_m),
                                       segments_per_piece);
}

}  // namespace skybake
