#include "data_formats/bake_file/exr_memory_stream.h"

#include <cstring>
#include <string>

#include <OpenEXR/IexBaseExc.h>

namespace skybake {

ExrMemoryStream::ExrMemoryStream(std::span<const std::byte> bytes, const char* name)
    : Imf::IStream(name), bytes_(bytes) {}

bool ExrMemoryStream::read(char c[], int n) {
  // position_ may lie past the end after a seek, so compare without
  // subtracting from the size first.
  if (n < 0 || position_ > bytes_.size() || static_cast<uint64_t>(n) > bytes_.size() - position_) {
    throw Iex::InputExc("Early end of file: reading " + std::to_string(n) + " bytes at offset " +
                        std::to_string(position_) + " of " + std::to_string(bytes_.size()));
  }
  if (n > 0) std::memcpy(c, bytes_.data() + position_, static_cast<size_t>(n));
  position_ += static_cast<uint64_t>(n);
  // OpenEXR's contract: false once the last byte has been read.
  return position_ < bytes_.size();
}

uint64_t ExrMemoryStream::tellg() { return position_; }

void ExrMemoryStream::seekg(uint64_t pos) { position_ = pos; }

}  // namespace skybake
