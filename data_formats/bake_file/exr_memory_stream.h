// An OpenEXR input stream over bytes already in memory, so a bake can be read
// from a buffer (an embedded asset, a network download, a fuzzer's input)
// through the same reader as a file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include <OpenEXR/ImfIO.h>

namespace skybake {

class ExrMemoryStream : public Imf::IStream {
 public:
  // `bytes` must outlive the stream; `name` is what OpenEXR's messages call it.
  ExrMemoryStream(std::span<const std::byte> bytes, const char* name);

  // Copies n bytes at the position and advances. Reading past the end throws
  // Iex::InputExc, as OpenEXR's own file stream does for a truncated file.
  bool read(char c[], int n) override;
  uint64_t tellg() override;
  // Any position is accepted; a read from beyond the end fails.
  void seekg(uint64_t pos) override;

 private:
  std::span<const std::byte> bytes_;
  uint64_t position_ = 0;
};

}  // namespace skybake
