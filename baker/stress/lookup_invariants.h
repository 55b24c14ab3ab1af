// The runtime's lookups (Sky) over a dense query set with the edge geometry
// included, checked against the invariants of invariants.h.
#pragma once

#include <vector>

#include "baker/stress/invariants.h"
#include "runtime/sky.h"

namespace skybake {

struct LookupInvariants {
  std::vector<InvariantResult> invariants;
  long long lookups = 0;
  double min_radiance = 0.0;  // over every radiance lookup and channel, W m^-2 sr^-1 nm^-1
  double max_radiance = 0.0;
};

// Cameras at the bottom and top radius, between them, 1 m below the ground
// and at 1e9 m; view zenith cosines -1, +1, a grid, and the rays tangent to
// the ground and to the top; suns from the zenith to beyond the lowest baked
// sun angle. Invariants: radiance and irradiance finite and >= 0,
// transmittance in [0, 1] and non-increasing along each ray, and continuity
// under kContinuityStep_rad changes of the view and sun angles. The view
// continuity pairs leave out a band of 1e-3 rad around the ground horizon,
// where ray lengths have a square-root singularity in the view angle and the
// ground occludes what lies behind the tangent point: real discontinuities.
LookupInvariants checkLookupInvariants(const Sky& sky);

}  // namespace skybake
