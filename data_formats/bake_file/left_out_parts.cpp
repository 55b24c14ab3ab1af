#include <algorithm>
#include <cstring>
#include <limits>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/bake_file/bake_file_attributes.h"

namespace skybake {

BakeContents storedContents(const BakeConfig& config, const AtmosphereDomain& domain) {
  BakeContents c;
  c.atmosphere = config.atmosphere;
  c.sizes = config.sizes;
  c.sizes.iteration.reset();
  c.density_view_size = c.sizes.scattering_mu;
  c.domain = domain;
  c.outputs = config.scene;
  c.precision = config.bake.precision;
  c.stored_fraction_bits = config.bake.stored_fraction_bits;
  c.combined_single_mie = config.bake.combined_single_mie && bakeStoresSingleMie(config.atmosphere);
  if (config.atmosphere.storesLaneGroups()) {
    // One group is an ordinary bake of its wavelengths, as the file reads back.
    if (config.colour_groups.size() == 1) {
      c.atmosphere = config.colour_groups[0];
    } else {
      c.lane_groups = config.colour_groups;
    }
  }
  // A colour bake's passes, whose optical depths the file keeps.
  if (config.atmosphere.storesCieXyz()) c.wavelength_groups = config.colour_groups;
  return c;
}

bool bakeStoresSingleMie(const BakeContents& contents) {
  if (contents.lane_groups.empty()) return bakeStoresSingleMie(contents.atmosphere);
  for (const AtmosphereParameters& g : contents.lane_groups) {
    if (bakeStoresSingleMie(g)) return true;
  }
  return false;
}

std::vector<LeftOutPart> leftOutParts(const BakeContents& c) {
  const TextureSizes& s = c.sizes;
  const uint64_t value_bytes = (c.precision == StoragePrecision::Half ? 2 : 4) * c.atmosphere.channelCount();
  const uint64_t table_4d =
      static_cast<uint64_t>(s.scattering_r) * s.scattering_mu * s.scattering_mu_s * s.scattering_nu * value_bytes;
  std::vector<LeftOutPart> out;
  if (!bakeStoresSingleMie(c)) {
    out.push_back({bake_file::kPartSingleMie, "no Mie scattering", table_4d});
  } else if (c.combined_single_mie) {
    // One channel of it moves into single_rayleigh.
    const int n = c.atmosphere.channelCount();
    out.push_back({bake_file::kPartSingleMie,
                   "bake.combined_single_mie: the first wavelength is a channel of single_rayleigh, the others "
                   "are rebuilt from the Rayleigh channels",
                   table_4d / n * (n - 1)});
  }
  // Rays toward the ground are integrated over the density when the 4D
  // tables leave them out ([scene] views_below_horizon), so it stays then.
  if (!c.outputs.radiance_to_points && c.domain.scattering_ground_views) {
    out.push_back({bake_file::kPartMultipleDensity, "scene.outputs without radiance_to_points",
                   table_4d / s.scattering_mu * c.density_view_size});
  }
  if (!c.outputs.ground_irradiance) {
    out.push_back({bake_file::kPartIrradiance, "scene.outputs without ground_irradiance",
                   static_cast<uint64_t>(s.irradiance_mu_s) * s.irradiance_r * value_bytes});
  }
  return out;
}

void clearLeftOutTables(const BakeContents& contents, BakeTables& tables) {
  if (contents.combined_single_mie) {
    approximateSingleMie(contents.atmosphere, tables.single_rayleigh, tables.single_mie);
  }
  for (const LeftOutPart& p : leftOutParts(contents)) {
    if (std::strcmp(p.part, bake_file::kPartSingleMie) == 0 && !contents.combined_single_mie) {
      tables.single_mie.texels = {};
    }
    if (std::strcmp(p.part, bake_file::kPartMultipleDensity) == 0) tables.multiple_density.texels = {};
    if (std::strcmp(p.part, bake_file::kPartIrradiance) == 0) tables.irradiance.texels = {};
  }
}

std::string combinedSingleMieChannelName(const AtmosphereParameters& a) {
  return "mie_" + channelName(a.wavelengths_nm[0]);
}

void approximateSingleMie(const AtmosphereParameters& a, const Texture4D& rayleigh, Texture4D& mie) {
  const int n = a.channelCount();
  // Per channel: (beta_R[0] / beta_M[0]) * (beta_M[c] / beta_R[c]); the
  // config check guarantees beta_R[0] and beta_M[0] > 0 (and beta_R[c] = 0
  // gives no Rayleigh light to take the shape from: 0).
  SpectrumD ratio(0.0);
  for (int c = 0; c < n; ++c) {
    ratio[c] = a.rayleigh_scattering[c] > 0.0f ? (double(a.rayleigh_scattering[0]) / a.mie_scattering[0]) *
                                                     (double(a.mie_scattering[c]) / a.rayleigh_scattering[c])
                                               : 0.0;
  }
  for (size_t i = 0; i < mie.texels.size(); ++i) {
    const Spectrum& ray = rayleigh.texels[i];
    Spectrum& m = mie.texels[i];
    // In double: with denormal Rayleigh values (dark, thick atmospheres) the
    // float quotient overflows; the result is clamped to the float range.
    const double per_rayleigh = ray[0] > 0.0f ? double(m[0]) / ray[0] : 0.0;
    for (int c = 1; c < n; ++c) {
      m[c] = static_cast<float>(std::min(ray[c] * per_rayleigh * ratio[c], double(std::numeric_limits<float>::max())));
    }
  }
}

bool leavesOut(const BakeContents& contents, const char* part) {
  for (const LeftOutPart& p : leftOutParts(contents)) {
    if (std::strcmp(p.part, part) == 0) return true;
  }
  return false;
}

}  // namespace skybake
