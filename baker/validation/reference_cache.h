// Reference results kept on disk, so validation is cheap after the first run.
// One JSON file per atmosphere and sample count, keyed by a hash of the
// atmosphere's parameters (not the table sizes: every bake of one atmosphere
// shares it), the reference solver's version and the sample count.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "data_formats/atmosphere_parameters.h"

namespace skybake {

struct CachedReference {
  SpectrumD value;
  SpectrumD standard_error;
  SpectrumD transmittance;
};

// FNV-1a, 64 bit: stable across platforms and runs, for cache keys and seeds.
uint64_t stableHash(const std::string& text);

// $SKYBAKE_CACHE_DIR, else $XDG_CACHE_HOME/skybake, else ~/.cache/skybake.
std::filesystem::path defaultReferenceCacheDirectory();

class ReferenceCache {
 public:
  // An empty directory disables the cache.
  ReferenceCache(const std::filesystem::path& directory, const AtmosphereParameters& atmosphere, int paths);

  std::optional<CachedReference> find(const std::string& query_key) const;
  void store(const std::string& query_key, const CachedReference& result);
  // Writes the file (atomically) if anything was stored.
  void save() const;
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::map<std::string, CachedReference> entries_;
  bool dirty_ = false;
};

}  // namespace skybake
