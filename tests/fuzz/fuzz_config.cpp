// libFuzzer target: parseConfig on arbitrary bytes. Configs are untrusted
// input (users write them; bake files carry them), so any outcome other than
// a BakeConfig or an Error(BadInput) is a finding. So is an accepted config
// whose canonical TOML does not read back to itself: configToToml is what a
// bake file stores and readBakeFile parses again, so a config that fails the
// round trip would bake a file that cannot be read.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>

#include "data_formats/config/config.h"
#include "data_formats/error.h"
#include "fuzz_checks.h"

namespace {

// The names error messages must start with.
constexpr const char* kSource = "fuzz.toml";
constexpr const char* kCanonicalSource = "canonical.toml";

void expectCanonicalRoundTrip(const skybake::BakeConfig& config) {
  const std::string canonical = skybake::configToToml(config);
  try {
    const skybake::BakeConfig again = skybake::parseConfig(canonical, kCanonicalSource);
    if (skybake::configToToml(again) != canonical) {
      skybake::fuzz::finding("canonical TOML reads back to a different config", canonical);
    }
  } catch (const skybake::Error& e) {
    skybake::fuzz::finding("canonical TOML of an accepted config is refused", std::string(e.what()) + "\n" + canonical);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  skybake::fuzz::expectOnlyBadInputErrors(kSource,
                                          [&] { expectCanonicalRoundTrip(skybake::parseConfig(text, kSource)); });
  return 0;
}
