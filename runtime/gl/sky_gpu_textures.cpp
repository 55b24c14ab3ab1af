#include "runtime/gl/sky_gpu_textures.h"

#include <algorithm>
#include <cstring>

#include "data_formats/error.h"

namespace skybake::gl {
namespace {

const Spectrum kZeroTexel(0.0f);

template <typename T>
std::vector<std::byte> copyBytes(const std::vector<T>& values) {
  std::vector<std::byte> bytes(values.size() * sizeof(T));
  if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

GpuTexture floatTexture(int dimensions, int width, int height, int depth, std::vector<std::byte> owned) {
  GpuTexture t;
  t.dimensions = dimensions;
  t.width = width;
  t.height = height;
  t.depth = depth;
  t.format = GpuTexelFormat::Rgba32f;
  t.owned = std::move(owned);
  return t;
}

GpuTexture texture2D(const Texture2D& table) {
  if (table.texels.empty()) return floatTexture(2, 1, 1, 1, copyBytes(std::vector<Spectrum>{kZeroTexel}));
  return floatTexture(2, table.width, table.height, 1, copyBytes(table.texels));
}

// The sun texels first_mu_s .. of a 4D table.
Texture4D fromSunTexel(const Texture4D& table, int first_mu_s) {
  Texture4D part(table.r_size, table.mu_size, table.mu_s_size - first_mu_s, table.nu_size);
  for (int r = 0; r < table.r_size; ++r)
    for (int mu = 0; mu < table.mu_size; ++mu)
      for (int nu = 0; nu < table.nu_size; ++nu)
        for (int mu_s = 0; mu_s < part.mu_s_size; ++mu_s)
          part.at(r, mu, mu_s, nu) = table.at(r, mu, mu_s + first_mu_s, nu);
  return part;
}

// A 4D table as a 3D texture: the atlas's memory order (x fastest, then
// mu, then r) is the 3D texture's (x, y, z), from sun texel `first_mu_s` on
// (singleScatteringFirstSunTexel). Half: its slice scales go to
// `slice_scales` (every sun texel's, the ones left out 1), lane `lane`.
GpuTexture texture4D(const Texture4D& whole, int first_mu_s, int channels, GpuTablePrecision precision,
                     std::vector<Spectrum>& slice_scales, int lane) {
  if (whole.texels.empty()) return floatTexture(3, 1, 1, 1, copyBytes(std::vector<Spectrum>{kZeroTexel}));
  Texture4D part;
  if (first_mu_s > 0) part = fromSunTexel(whole, first_mu_s);
  const Texture4D& table = first_mu_s > 0 ? part : whole;
  if (precision == GpuTablePrecision::Float) {
    GpuTexture t = floatTexture(3, table.atlasWidth(), table.mu_size, table.r_size, {});
    if (first_mu_s > 0) {
      t.owned = copyBytes(table.texels);
    } else {
      t.borrowed = std::as_bytes(std::span(table.texels));
    }
    return t;
  }
  const HalfTable4D half = halfTable4D(table, channels);
  // Slice s is (r, mu_s) = (s / mu_s_size, s % mu_s_size) of the part.
  for (size_t s = 0; s < half.slice_scales.size(); ++s) {
    const size_t r = s / table.mu_s_size, mu_s = s % table.mu_s_size;
    slice_scales[r * whole.mu_s_size + mu_s + first_mu_s][lane] = half.slice_scales[s];
  }
  GpuTexture t = floatTexture(3, table.atlasWidth(), table.mu_size, table.r_size, copyBytes(half.values));
  t.format = half.components == 3 ? GpuTexelFormat::Rgb16f : GpuTexelFormat::Rgba16f;
  return t;
}

// The optical-depth texture: the bake's table, and below it a colour
// bake's wavelength groups' tables in order (the integral's passes,
// skybake_integral_passes).
Texture2D opticalDepthRows(const Sky& sky) {
  Texture2D stacked = sky.tables().optical_depth;
  for (const Texture2D& g : sky.wavelengthOpticalDepth()) {
    if (g.width != stacked.width) throw Error(ErrorKind::Internal, "wavelength optical depths of another width");
    stacked.texels.insert(stacked.texels.end(), g.texels.begin(), g.texels.end());
    stacked.height += g.height;
  }
  return stacked;
}

}  // namespace

int gpuTexelBytes(GpuTexelFormat format) {
  switch (format) {
    case GpuTexelFormat::Rgba32f:
      return 16;
    case GpuTexelFormat::Rgb16f:
      return 6;
    case GpuTexelFormat::Rgba16f:
      return 8;
  }
  return 0;
}

std::vector<GpuTexture> skyGpuTextures(const Sky& sky, GpuTablePrecision precision) {
  const BakeTables& t = sky.tables();
  const int channels = sky.channelCount();
  // Lanes x, y, z, w: single Rayleigh, single Mie, multiple scattering, its
  // density (skybake_parameters.glsl); 1 where a table is float or absent.
  const Texture4D& shape = t.single_rayleigh;
  Texture2D slice_scales(std::max(shape.mu_s_size, 1), std::max(shape.r_size, 1));
  for (Spectrum& scale : slice_scales.texels) scale = Spectrum(1.0f);
  std::vector<GpuTexture> textures;
  textures.push_back(texture2D(opticalDepthRows(sky)));
  const int single_first =
      singleScatteringFirstSunTexel(sky.contents().domain, ScatteringSizes::fromTextureSizes(sky.contents().sizes));
  textures.push_back(texture4D(t.single_rayleigh, single_first, channels, precision, slice_scales.texels, 0));
  textures.push_back(texture4D(t.single_mie, single_first, channels, precision, slice_scales.texels, 1));
  textures.push_back(texture4D(t.multiple_scattering, 0, channels, precision, slice_scales.texels, 2));
  textures.push_back(texture4D(t.multiple_density, 0, channels, precision, slice_scales.texels, 3));
  textures.push_back(texture2D(t.irradiance));
  textures.push_back(texture2D(slice_scales));
  for (size_t i = 0; i < textures.size(); ++i) textures[i].sampler = kSkySamplerNames[i];
  return textures;
}

}  // namespace skybake::gl
