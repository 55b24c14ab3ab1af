// Optical depth along a ray, integrated directly from the density profiles.
#pragma once

#include "runtime/atmosphere_media.h"

namespace skybake {

// Optical depth (per channel, dimensionless) along the ray from radius r with
// zenith cosine mu over distances [0, length_m]. The ray is split where it
// crosses a layer boundary or a kink of a linear layer (where its value is
// clamped at 0 or 1), so every piece is smooth and Gauss-Legendre converges
// fast; the planet's surface does not stop the ray.
SpectrumD opticalDepthAlongRay(const AtmosphereMedia& media, double r, double mu, double length_m);

// Optical depth from (r, mu) to the top boundary.
SpectrumD opticalDepthToTop(const AtmosphereMedia& media, double r, double mu);

}  // namespace skybake
