#include "baker/validation/reference_cache.h"

#include <cstdlib>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "data_formats/atomic_file.h"
#include "data_formats/config.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

// Bumped whenever the reference solver's results change: old caches are then
// simply not found.
constexpr int kReferenceSolverVersion = 4;  // 4: the sun disk counted as the bake counts it

nlohmann::json toJson(const SpectrumD& s) { return {s.x, s.y, s.z, s.w}; }
SpectrumD spectrumFromJson(const nlohmann::json& j) { return {j.at(0), j.at(1), j.at(2), j.at(3)}; }

}  // namespace

uint64_t stableHash(const std::string& text) {
  uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::filesystem::path defaultReferenceCacheDirectory() {
  if (const char* dir = std::getenv("SKYBAKE_CACHE_DIR"); dir != nullptr && *dir != '\0') return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::filesystem::path(xdg) / "skybake";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".cache" / "skybake";
  }
  return ".skybake-cache";
}

namespace {

// What the cache key holds for the tables' domain and size, whatever the
// defaults are now: the defaults when the key was introduced.
constexpr double kKeySunMaxZenith_deg = 102.0;
constexpr int kKeyScatteringMuS = 32;

}  // namespace

ReferenceCache::ReferenceCache(const std::filesystem::path& directory, const AtmosphereParameters& atmosphere,
                               int paths) {
  if (directory.empty()) return;
  BakeConfig physics_only;  // fixed sizes and default settings: only the atmosphere enters the key
  physics_only.name = "reference";
  physics_only.atmosphere = atmosphere;
  // The lowest tabulated sun is the tables' domain, not physics: bakes that
  // differ only in it share their reference. It and the sizes are pinned to
  // the values the keys were first made with (not the current defaults), so
  // that a change of a default keeps every cached reference.
  physics_only.atmosphere.sun_max_zenith_deg = kKeySunMaxZenith_deg;
  physics_only.sizes = TextureSizes{};
  physics_only.sizes.scattering_mu_s = kKeyScatteringMuS;
  const uint64_t key =
      stableHash(fmt::format("solver {}\npaths {}\n{}", kReferenceSolverVersion, paths, configToToml(physics_only)));
  file_ = directory / fmt::format("reference-{:016x}.json", key);
  std::ifstream in(file_);
  if (!in) return;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("entries")) return;  // unreadable: recompute, overwrite later
  try {
    for (const auto& [query, e] : j["entries"].items()) {
      entries_[query] = {spectrumFromJson(e.at("value")), spectrumFromJson(e.at("standard_error")),
                         spectrumFromJson(e.at("transmittance"))};
    }
  } catch (const std::exception&) {
    entries_.clear();
  }
}

std::optional<CachedReference> ReferenceCache::find(const std::string& query_key) const {
  auto it = entries_.find(query_key);
  if (it == entries_.end()) return std::nullopt;
  return it->second;
}

void ReferenceCache::store(const std::string& query_key, const CachedReference& result) {
  if (file_.empty()) return;
  entries_[query_key] = result;
  dirty_ = true;
}

void ReferenceCache::save() const {
  if (file_.empty() || !dirty_) return;
  nlohmann::json entries = nlohmann::json::object();
  for (const auto& [query, e] : entries_) {
    entries[query] = {{"value", toJson(e.value)},
                      {"standard_error", toJson(e.standard_error)},
                      {"transmittance", toJson(e.transmittance)}};
  }
  std::error_code error;
  std::filesystem::create_directories(file_.parent_path(), error);
  if (error) {
    throwBadInput(fmt::format("{}: cannot create the reference cache directory: {}", file_.parent_path().string(),
                              error.message()));
  }
  writeFileContentsAtomically(file_, nlohmann::json{{"entries", entries}}.dump());
}

}  // namespace skybake
