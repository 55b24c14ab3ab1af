#include <cstring>

#include "bake_file.h"
#include "bake_file_attributes.h"

namespace skybake {

std::vector<LeftOutPart> leftOutParts(const BakeConfig& c) {
  const TextureSizes& s = c.sizes;
  const uint64_t value_bytes = (c.bake.precision == StoragePrecision::Half ? 2 : 4) * c.atmosphere.channelCount();
  const uint64_t table_4d = static_cast<uint64_t>(s.scattering_r) * s.scattering_mu * s.scattering_mu_s *
                            s.scattering_nu * value_bytes;
  std::vector<LeftOutPart> out;
  if (!bakeStoresSingleMie(c.atmosphere)) {
    out.push_back({bake_file::kPartSingleMie, "no Mie scattering", table_4d});
  }
  if (!c.scene.radiance_to_points) {
    out.push_back({bake_file::kPartMultipleDensity, "scene.outputs without radiance_to_points", table_4d});
  }
  if (!c.scene.ground_irradiance) {
    out.push_back({bake_file::kPartIrradiance, "scene.outputs without ground_irradiance",
                   static_cast<uint64_t>(s.irradiance_mu_s) * s.irradiance_r * value_bytes});
  }
  return out;
}

void clearLeftOutTables(const BakeConfig& config, BakeTables& tables) {
  for (const LeftOutPart& p : leftOutParts(config)) {
    if (std::strcmp(p.part, bake_file::kPartSingleMie) == 0) tables.single_mie.texels = {};
    if (std::strcmp(p.part, bake_file::kPartMultipleDensity) == 0) tables.multiple_density.texels = {};
    if (std::strcmp(p.part, bake_file::kPartIrradiance) == 0) tables.irradiance.texels = {};
  }
}

bool leavesOut(const BakeConfig& config, const char* part) {
  for (const LeftOutPart& p : leftOutParts(config)) {
    if (std::strcmp(p.part, part) == 0) return true;
  }
  return false;
}

}  // namespace skybake
