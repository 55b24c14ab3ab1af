// The range each table's values must lie in. The writer refuses to write a
// table outside it (a config whose numbers overflow float) and the reader
// refuses a file that holds one (a damaged or forged file), so a bake can
// never write what its own reader rejects.
#pragma once

#include <string>
#include <vector>

#include "data_formats/spectra/spectrum.h"

namespace skybake {

// Larger values than this are refused: the config check keeps real bakes
// far below it (data_formats/config/config_validate.cpp), and lookups multiply
// table values by phase functions and sum them, which must stay finite in
// float (3.4e38).
inline constexpr float kMaxTableValue = 1e36f;

// Throws Error(BadInput) "<source>: part '<part>' holds <value> at texel <i>
// (channel <c>): <reason>" for the first value of the first `channels`
// lanes that is not finite, negative (every table holds optical depths,
// radiances, irradiances or densities, all >= 0) or above kMaxTableValue.
void checkTableValues(const std::string& source, const char* part, const std::vector<Spectrum>& texels, int channels);

}  // namespace skybake
