#include "baker/validation/reference_cache.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "data_formats/atomic_file.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

// Bumped whenever the reference solver's results change: old caches are then
// simply not found.
constexpr int kReferenceSolverVersion = 4;  // 4: the sun disk counted as the bake counts it

nlohmann::json toJson(const SpectrumD& s) { return {s.x, s.y, s.z, s.w}; }
SpectrumD spectrumFromJson(const nlohmann::json& j) { return {j.at(0), j.at(1), j.at(2), j.at(3)}; }

// Whether a cached result lies in the range the reference solver gives:
// radiance, irradiance and their standard errors finite and >= 0,
// transmittance in [0, 1], the colour halves' difference finite. Anything
// else was not written by skybake (an edited or damaged file) and would be
// used as the truth: a -5 skipped its query, a 1000 reported a 70 % error.
bool withinPhysicalRange(const CachedReference& e) {
  for (int c = 0; c < 4; ++c) {
    if (!(std::isfinite(e.value[c]) && e.value[c] >= 0.0 && std::isfinite(e.standard_error[c]) &&
          e.standard_error[c] >= 0.0 && e.transmittance[c] >= 0.0 && e.transmittance[c] <= 1.0 &&
          std::isfinite(e.half_difference[c]))) {
      return false;
    }
  }
  return true;
}

// A chunk name no other writer uses: this host (nodes of a cluster share the
// cache), this process, the time it started writing and a counter.
std::string uniqueChunkName(int counter) {
  char host[256] = {};
  if (::gethostname(host, sizeof(host) - 1) != 0 || host[0] == '\0') std::snprintf(host, sizeof(host), "host");
  const auto now_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  return fmt::format("{}-{}-{}-{}.json", host, ::getpid(), now_ns, counter);
}

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
constexpr int kKeyIrradianceMuS = 64;
constexpr StoragePrecision kKeyPrecision = StoragePrecision::Float;

// The text of an atmosphere that enters a cache key: its config with fixed
// sizes and default settings, so that only the atmosphere counts.
std::string atmosphereKeyText(const AtmosphereParameters& atmosphere) {
  BakeConfig physics_only;
  physics_only.name = "reference";
  physics_only.atmosphere = atmosphere;
  // The lowest tabulated sun is the tables' domain, not physics: bakes that
  // differ only in it share their reference. It, the sizes and the storage
  // precision are pinned to
  // the values the keys were first made with (not the current defaults), so
  // that a change of a default keeps every cached reference.
  physics_only.atmosphere.sun_max_zenith_deg = kKeySunMaxZenith_deg;
  physics_only.sizes = TextureSizes{};
  physics_only.sizes.scattering_mu_s = kKeyScatteringMuS;
  physics_only.sizes.irradiance_mu_s = kKeyIrradianceMuS;
  physics_only.bake.precision = kKeyPrecision;
  return configToToml(physics_only);
}

// Bumped whenever the colour reference's results change (its wavelengths,
// their groups, its seeds), beside the solver's own version.
constexpr int kColourReferenceVersion = 2;  // 2: two independent halves

}  // namespace

ReferenceCache::ReferenceCache(const std::filesystem::path& directory, const AtmosphereParameters& atmosphere,
                               int paths) {
  if (directory.empty()) return;
  const uint64_t key =
      stableHash(fmt::format("solver {}\npaths {}\n{}", kReferenceSolverVersion, paths, atmosphereKeyText(atmosphere)));
  openDirectory(directory / fmt::format("reference-{:016x}", key));
}

ReferenceCache::ReferenceCache(const std::filesystem::path& directory,
                               const std::vector<AtmosphereParameters>& colour_groups, int paths) {
  if (directory.empty()) return;
  std::string text =
      fmt::format("colour {}\nsolver {}\npaths {}\n", kColourReferenceVersion, kReferenceSolverVersion, paths);
  for (const AtmosphereParameters& group : colour_groups) text += atmosphereKeyText(group);
  openDirectory(directory / fmt::format("colour-reference-{:016x}", stableHash(text)));
}

bool ReferenceCache::readChunkFile(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    if (std::filesystem::exists(file, error)) notes_.push_back(file.string() + ": not a regular file; skipped");
    return false;
  }
  std::map<std::string, CachedReference> read;
  size_t discarded = 0;
  try {
    std::ifstream in(file);
    if (!in) return false;  // removed by a merging reader meanwhile: its queries are recomputed
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (!j.is_object() || !j.contains("entries") || !j["entries"].is_object()) {
      notes_.push_back(file.string() + ": not a reference cache chunk; skipped");
      return false;
    }
    for (const auto& [query, e] : j["entries"].items()) {
      const CachedReference entry{
          spectrumFromJson(e.at("value")), spectrumFromJson(e.at("standard_error")),
          spectrumFromJson(e.at("transmittance")),
          e.contains("half_difference") ? spectrumFromJson(e.at("half_difference")) : SpectrumD(0.0)};
      if (withinPhysicalRange(entry)) {
        read[query] = entry;
      } else {
        ++discarded;
      }
    }
  } catch (const std::exception& e) {
    notes_.push_back(fmt::format("{}: unreadable ({}); skipped", file.string(), e.what()));
    return false;
  }
  if (discarded > 0) {
    notes_.push_back(fmt::format("{}: {} value(s) outside the reference's physical range discarded; recomputed",
                                 file.string(), discarded));
  }
  entries_.merge(read);
  return true;
}

void ReferenceCache::openDirectory(const std::filesystem::path& directory) {
  directory_ = directory;
  // A cache written as one file (before caches were directories) is read as
  // one more chunk, never removed.
  readChunkFile(std::filesystem::path(directory_.string() + ".json"));
  readChunks();
}

void ReferenceCache::readChunks() {
  std::error_code error;
  std::vector<std::filesystem::path> read;
  for (const auto& entry : std::filesystem::directory_iterator(directory_, error)) {
    const std::string name = entry.path().filename().string();
    // Temporary files of writes in progress start with a dot.
    if (name.empty() || name[0] == '.' || entry.path().extension() != ".json") continue;
    if (readChunkFile(entry.path())) read.push_back(entry.path());
  }
  if (read.size() <= kReferenceChunksBeforeMerge) return;
  for (const auto& [query, e] : entries_) unsaved_.push_back(query);
  try {
    saveChunk();
  } catch (const Error&) {
    unsaved_.clear();  // a cache this process may only read: merging is left to one that may write
    return;
  }
  for (const std::filesystem::path& chunk : read) std::filesystem::remove(chunk, error);
}

std::optional<CachedReference> ReferenceCache::find(const std::string& query_key) const {
  auto it = entries_.find(query_key);
  if (it == entries_.end()) return std::nullopt;
  return it->second;
}

void ReferenceCache::store(const std::string& query_key, const CachedReference& result) {
  if (directory_.empty()) return;
  if (entries_.insert_or_assign(query_key, result).second) unsaved_.push_back(query_key);
}

void ReferenceCache::saveChunkIfWritable() {
  if (!writable_) return;
  try {
    saveChunk();
  } catch (const Error& e) {
    writable_ = false;
    unsaved_.clear();
    notes_.push_back(
        fmt::format("the reference cache cannot be written ({}): the results are reported, not kept", e.what()));
  }
}

void ReferenceCache::saveChunk() {
  if (directory_.empty() || unsaved_.empty()) return;
  nlohmann::json entries = nlohmann::json::object();
  for (const std::string& query : unsaved_) {
    const CachedReference& e = entries_.at(query);
    entries[query] = {{"value", toJson(e.value)},
                      {"standard_error", toJson(e.standard_error)},
                      {"transmittance", toJson(e.transmittance)}};
    if (e.half_difference != SpectrumD(0.0)) entries[query]["half_difference"] = toJson(e.half_difference);
  }
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error) {
    throwBadInput(
        fmt::format("{}: cannot create the reference cache directory: {}", directory_.string(), error.message()));
  }
  writeFileContentsAtomically(directory_ / uniqueChunkName(chunks_written_++),
                              nlohmann::json{{"entries", entries}}.dump());
  unsaved_.clear();
}

}  // namespace skybake
