// Reference results kept on disk, so validation is cheap after the first run.
// One directory per atmosphere and sample count, named by a hash of the
// atmosphere's parameters (not the table sizes: every bake of one atmosphere
// shares it), the reference solver's version and the sample count.
//
// The directory holds chunk files, each written once, atomically, under a
// name no other process uses. Readers merge every chunk. So any number of
// processes, on one machine or on the nodes of a cluster sharing the file
// system, can fill one cache at the same time without locks, and a process
// killed part way (a cluster job at its time limit) keeps every chunk it
// saved: computeReferenceValues saves one at least every
// kReferenceCheckpointSeconds.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "data_formats/config/atmosphere_parameters.h"

namespace skybake {

struct CachedReference {
  SpectrumD value;
  SpectrumD standard_error;
  SpectrumD transmittance;
  // A colour reference's (A - B) / 2 of its two halves (colour_reference.h);
  // zero, and not written, for a spectral reference.
  SpectrumD half_difference{0.0};
};

// FNV-1a, 64 bit: stable across platforms and runs, for cache keys and seeds.
uint64_t stableHash(const std::string& text);

// $SKYBAKE_CACHE_DIR, else $XDG_CACHE_HOME/skybake, else ~/.cache/skybake.
std::filesystem::path defaultReferenceCacheDirectory();

// Once a cache holds more chunk files than this, the next reader merges them
// into one: thousands of small files (a long history of checkpoints) would
// make every later start slow. Merging writes the merged chunk before it
// removes the chunks it read, so no entry is ever lost; a reader that misses
// a removed chunk only recomputes its queries, to the same values.
inline constexpr size_t kReferenceChunksBeforeMerge = 32;

class ReferenceCache {
 public:
  // An empty directory disables the cache.
  ReferenceCache(const std::filesystem::path& directory, const AtmosphereParameters& atmosphere, int paths);

  // The cache of a colour reference (colour_reference.h): CIE XYZ in the
  // first three lanes of each value, from the atmospheres of its wavelength
  // groups. Its directory is named "colour-reference-" and a hash of every
  // group's atmosphere, so it never shares a directory with a spectral
  // reference (whose directories stay as they were).
  ReferenceCache(const std::filesystem::path& directory, const std::vector<AtmosphereParameters>& colour_groups,
                 int paths);

  std::optional<CachedReference> find(const std::string& query_key) const;
  // Kept in memory until the next saveChunk().
  void store(const std::string& query_key, const CachedReference& result);
  // Writes what was stored since the last call as a new chunk file (nothing
  // if nothing was). Throws Error(BadInput) if the directory cannot be made.
  void saveChunk();
  // saveChunk, but a cache that cannot be written (a read-only directory, a
  // full disk) only keeps its results in memory from then on: a note says
  // why, and the work goes on.
  void saveChunkIfWritable();
  // What the cache found and did about it (entries out of their physical
  // range discarded, unreadable chunks skipped, a write refused), each
  // naming the file or directory; empty when all was well.
  const std::vector<std::string>& notes() const { return notes_; }
  // This atmosphere's directory (empty if the cache is disabled).
  const std::filesystem::path& directory() const { return directory_; }
  size_t size() const { return entries_.size(); }

 private:
  void readChunks();
  // Adds a chunk file's entries within their physical range; false if it
  // cannot be read (its queries are then recomputed). Notes what it skips.
  bool readChunkFile(const std::filesystem::path& file);
  void openDirectory(const std::filesystem::path& directory);

  std::filesystem::path directory_;
  std::map<std::string, CachedReference> entries_;
  std::vector<std::string> unsaved_;
  std::vector<std::string> notes_;
  int chunks_written_ = 0;
  bool writable_ = true;
};

}  // namespace skybake
