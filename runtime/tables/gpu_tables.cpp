// The 4D tables as skybake_gl uploads them (gpu_tables.h).
#include "runtime/tables/gpu_tables.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include <Imath/half.h>

#include "data_formats/bake_file/half_slices.h"

namespace skybake {
namespace {

// Bytes of an RGBA32F texel.
constexpr uint64_t kFloatTexelBytes = 16;

int halfComponents(int channels) { return channels <= 3 ? 3 : 4; }

}  // namespace

HalfTable4D halfTable4D(const Texture4D& table, int channels) {
  HalfTable4D out;
  out.components = halfComponents(channels);
  const HalfSliceLayout layout = HalfSliceLayout::of(table);
  std::vector<int> exponents = halfSliceExponents(layout, {{&table.texels, channels}});
  for (int& e : exponents) e = std::clamp(e, kMinGpuSliceExponent, kMaxGpuSliceExponent);
  out.slice_scales.resize(exponents.size());
  for (size_t s = 0; s < exponents.size(); ++s) out.slice_scales[s] = std::ldexp(1.0f, exponents[s]);
  out.values.resize(table.texels.size() * out.components);
  if (table.texels.empty()) return out;
  layout.forEachTexel([&](size_t t, size_t slice) {
    const int exponent = exponents[slice];
    for (int c = 0; c < out.components; ++c) {
      const Imath::half value(c < channels ? scaledByPowerOfTwo(table.texels[t][c], -exponent) : 0.0f);
      out.values[t * out.components + c] = value.bits();
    }
  });
  return out;
}

int singleScatteringFirstSunTexel(const AtmosphereDomain& domain, const ScatteringSizes& sizes) {
  int first = 0;
  while (first + 1 < sizes.mu_s && muSFromScatteringTexel(domain, sizes, first + 1) <= 0.0) ++first;
  return first;
}

GpuUploadBytes gpuUploadBytes(const BakeContents& contents, GpuTablePrecision precision) {
  const TextureSizes& s = contents.sizes;
  const uint64_t texels_4d =
      static_cast<uint64_t>(s.scattering_r) * s.scattering_mu * s.scattering_mu_s * s.scattering_nu;
  const uint64_t texel_bytes =
      precision == GpuTablePrecision::Half ? 2 * halfComponents(contents.atmosphere.channelCount()) : kFloatTexelBytes;
  const uint64_t density_texels = texels_4d / s.scattering_mu * contents.density_view_size;
  const ScatteringSizes scattering = ScatteringSizes::fromTextureSizes(s);
  const uint64_t single_texels =
      texels_4d / s.scattering_mu_s * (s.scattering_mu_s - singleScatteringFirstSunTexel(contents.domain, scattering));
  GpuUploadBytes bytes;
  for (const char* part : {bake_file::kPartSingleRayleigh, bake_file::kPartSingleMie,
                           bake_file::kPartMultipleScattering, bake_file::kPartMultipleDensity}) {
    // A combined single Mie table is rebuilt in memory from its first
    // channel (approximateSingleMie) and uploaded as the Rayleigh one.
    const std::string_view name(part);
    const bool uploaded =
        name == bake_file::kPartSingleMie ? bakeStoresSingleMie(contents) : !leavesOut(contents, part);
    const uint64_t texels = name == bake_file::kPartMultipleDensity      ? density_texels
                            : name == bake_file::kPartMultipleScattering ? texels_4d
                                                                         : single_texels;
    bytes.tables_4d += (uploaded ? texels : 1) * texel_bytes;
  }
  const uint64_t irradiance_texels =
      leavesOut(contents, bake_file::kPartIrradiance) ? 1 : static_cast<uint64_t>(s.irradiance_mu_s) * s.irradiance_r;
  // A colour bake's wavelength optical depths: its groups' tables, stacked
  // below the bake's own in the optical-depth texture.
  const uint64_t groups = contents.wavelength_groups.size();
  const uint64_t wavelength_depth_texels = groups * static_cast<uint64_t>(s.transmittance_mu) * s.transmittance_r;
  bytes.tables_2d =
      (static_cast<uint64_t>(s.transmittance_mu) * s.transmittance_r + irradiance_texels + wavelength_depth_texels) *
      kFloatTexelBytes;
  // Every (r, mu_s) slice's scale, 1 throughout for a float upload (the
  // GLSL reads them either way).
  bytes.slice_scales = static_cast<uint64_t>(s.scattering_r) * s.scattering_mu_s * kFloatTexelBytes;
  return bytes;
}

}  // namespace skybake
