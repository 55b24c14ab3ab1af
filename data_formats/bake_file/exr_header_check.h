// The headers of an OpenEXR file checked by OpenEXRCore before OpenEXR's C++
// reader sees them. The C++ reader of OpenEXR 3.1 sizes each attribute's
// buffer from the size the file declares and reads some attribute types
// (channel lists) past that size, so a few corrupt bytes in a small file can
// make it allocate and fill gigabytes. OpenEXRCore, OpenEXR's C layer, parses
// the same headers checking every attribute against its type and the file's
// size, and allocates nothing it has not checked.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

namespace skybake {

// Throw Error(BadInput) "<source>: OpenEXR header: <reason>" unless the
// headers of the file (or of the whole file held in `bytes`) parse strictly.
// Pixel data is not looked at.
void checkExrHeaders(const std::filesystem::path& path, const std::string& source);
void checkExrHeaders(std::span<const std::byte> bytes, const std::string& source);

}  // namespace skybake
