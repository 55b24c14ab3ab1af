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

#include "data_formats/bake_file.h"
#include "data_formats/error.h"
#include "fuzz_checks.h"

namespace {

// The name error messages must start with.
constexpr const char* kSource = "fuzz.exr";

void expectTableSizes(const skybake::BakeFile& bake) {
  const skybake::TextureSizes& s = bake.contents.sizes;
  const skybake::BakeTables& t = bake.tables;
  const size_t texels_4d = static_cast<size_t>(s.scattering_r) * s.scattering_mu * s.scattering_mu_s * s.scattering_nu;
  const bool ok =
      t.optical_depth.texels.size() == static_cast<size_t>(s.transmittance_mu) * s.transmittance_r &&
      t.irradiance.texels.size() ==
          (bake.contents.outputs.ground_irradiance ? static_cast<size_t>(s.irradiance_mu_s) * s.irradiance_r : 0) &&
      t.single_rayleigh.texels.size() == texels_4d &&
      t.single_mie.texels.size() == (skybake::bakeStoresSingleMie(bake.contents.atmosphere) ? texels_4d : 0) &&
      t.multiple_scattering.texels.size() == texels_4d &&
      t.multiple_density.texels.size() == (bake.contents.outputs.radiance_to_points ? texels_4d : 0);
  if (!ok) skybake::fuzz::finding("accepted bake's tables do not match its attributes", "fuzz.exr");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  skybake::fuzz::expectOnlyBadInputErrors(kSource,
                                          [&] { expectTableSizes(skybake::readBakeFileFromMemory(bytes, kSource)); });
  return 0;
}
