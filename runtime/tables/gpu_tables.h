// The 4D tables as skybake_gl uploads them (runtime/gl/sky_gl_resources.h),
// computed without OpenGL so that `skybake info` can state an upload's size
// and the conversion lives beside the file's own half storage.
//
// Half (the default): each 4D table as 16-bit floats, one value per
// channel (RGB16F for up to 3 channels, RGBA16F for 4), every (r, mu_s) slice
// scaled by its own power of two as a half file stores it
// (data_formats/bake_file/half_slices.h), the scales in one small 2D table the shader
// multiplies each texel by. A half bake (bake.precision = "half") uploads
// exactly its values; a float bake loses half's rounding, 2^-11 (4.9e-4) of
// each value at most. Float: RGBA32F, the values as loaded. The 2D tables
// (optical depth, irradiance) are RGBA32F either way: a transmittance
// exp(-depth) multiplies the depth's rounding by the depth.
#pragma once

#include <cstdint>
#include <vector>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {

enum class GpuTablePrecision { Half, Float };

// The exponents a GPU scale can take: float's normal range, so that 2^e is
// exact in the scale table. A slice whose largest value is below 2^-112
// (2e-34; only absurd atmospheres have one) keeps the lowest, and its values
// become half subnormals or 0, as float arithmetic on a GPU would make them.
inline constexpr int kMinGpuSliceExponent = -126;
inline constexpr int kMaxGpuSliceExponent = 127;

// One 4D table converted for a half upload: `components` 16-bit values per
// texel in the atlas order (Texture4D), each the texel's value over its
// slice's scale, as raw half bits.
struct HalfTable4D {
  int components = 0;  // 3 (RGB16F) or 4 (RGBA16F)
  std::vector<uint16_t> values;
  std::vector<float> slice_scales;  // 2^e per (r, mu_s) slice, index r * mu_s_size + mu_s
};
HalfTable4D halfTable4D(const Texture4D& table, int channels);

// The first sun (mu_s) texel of the single-scattering tables that a lookup
// reads: the last at or below the horizon (0 where the axis starts above
// it). Lookups take single scattering from the tables only where the sun
// is above the horizon everywhere they read them, and integrate it along
// the ray elsewhere (Sky::singleScattering; the GLSL alike), so the texels
// before this one are never read: an upload leaves them out (18 of the
// default 41 sun texels, 13.5 MiB of its half floats; the GLSL finds where
// the uploaded ones start from the texture's width,
// skybakeUploadedSunTexels).
int singleScatteringFirstSunTexel(const AtmosphereDomain& domain, const ScatteringSizes& sizes);

// Bytes of texture memory an upload of a bake with these contents takes, as
// the GL formats' sizes (a driver may pad RGB16F to 8 bytes).
struct GpuUploadBytes {
  uint64_t tables_4d = 0;     // the 4D tables the file holds (a left-out one is one texel)
  uint64_t tables_2d = 0;     // optical depth, irradiance, a colour bake's wavelength optical depths
  uint64_t slice_scales = 0;  // the scale table
  uint64_t total() const { return tables_4d + tables_2d + slice_scales; }
};
GpuUploadBytes gpuUploadBytes(const BakeContents& contents, GpuTablePrecision precision);

}  // namespace skybake
