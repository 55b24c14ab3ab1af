// libFuzzer target: readBakeFileFromMemory on arbitrary bytes. A bake file is
// untrusted input (downloaded, copied, half-written), so any outcome other
// than a BakeFile or an Error(BadInput) is a finding. A bake that is accepted
// must hold exactly the tables its attributes describe, since the runtime indexes
// them by those sizes without further checks.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>
#include <string>

#include "data_formats/bake_file/bake_file.h"
#include "data_formats/error.h"
#include "fuzz_checks.h"

namespace {

// The name error messages must start with.
constexpr const char* kSource = "fuzz.exr";

// One lane group's tables (the bake's own, or a spectral bake's group g).
bool tableSizesMatch(const skybake::BakeContents& contents, const skybake::AtmosphereParameters& group,
                     const skybake::BakeTables& t) {
  const skybake::TextureSizes& s = contents.sizes;
  const size_t texels_4d = static_cast<size_t>(s.scattering_r) * s.scattering_mu * s.scattering_mu_s * s.scattering_nu;
  return t.optical_depth.texels.size() == static_cast<size_t>(s.transmittance_mu) * s.transmittance_r &&
         t.irradiance.texels.size() ==
             (contents.outputs.ground_irradiance ? static_cast<size_t>(s.irradiance_mu_s) * s.irradiance_r : 0) &&
         t.single_rayleigh.texels.size() == texels_4d &&
         t.single_mie.texels.size() == (skybake::bakeStoresSingleMie(group) ? texels_4d : 0) &&
         t.multiple_scattering.texels.size() == texels_4d &&
         t.multiple_density.texels.size() ==
             (contents.outputs.radiance_to_points ? texels_4d / s.scattering_mu * contents.density_view_size : 0);
}

void expectTableSizes(const skybake::BakeFile& bake) {
  const skybake::BakeContents& c = bake.contents;
  bool ok = c.lane_groups.empty() ? tableSizesMatch(c, c.atmosphere, bake.tables)
                                  : bake.lane_group_tables.size() == c.lane_groups.size();
  for (size_t g = 0; ok && g < bake.lane_group_tables.size(); ++g) {
    ok = tableSizesMatch(c, c.lane_groups[g], bake.lane_group_tables[g]);
  }
  if (!ok) skybake::fuzz::finding("accepted bake's tables do not match its attributes", "fuzz.exr");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  skybake::fuzz::expectOnlyBadInputErrors(kSource,
                                          [&] { expectTableSizes(skybake::readBakeFileFromMemory(bytes, kSource)); });
  return 0;
}
