// Radiance scattered toward the start of a segment of a view ray, by direct
// quadrature of the scattering sources along it: single scattering from the
// density profiles and the transmittance table, multiple scattering from the
// tabulated density. Radiance to a point uses it over short segments and in
// twilight, and bakes without views below the horizon for rays to the ground.
#pragma once

#include "data_formats/bake_file/bake_file.h"
#include "runtime/physics/multiple_scattering_phase.h"
#include "runtime/sky.h"
#include "runtime/tables/table_sampler.h"

namespace skybake {

// In-scattered radiance over [0, length] of the ray (r, mu) with the sun at
// (mu_s, nu), each source attenuated back to the start, and the segment's
// transmittance. `subintervals` of 4 Gauss nodes; `with_single` false leaves
// single scattering out (callers that integrate it on their own).
RadianceAndTransmittance directSegmentRadiance(const TableSampler& sampler, const BakeTables& t,
                                               const AtmosphereParameters& a,
                                               const MultipleScatteringPhase& multiple_shape, double r, double mu,
                                               double mu_s, double nu, double length, int subintervals,
                                               bool with_single);

}  // namespace skybake
