// Checks on a file before skybake reads it: the one place that decides what
// a config, a spectrum CSV or a bake file may be. A device (/dev/zero) never
// ends, a named pipe blocks the reader until something writes to it, and a
// file of gigabytes is read whole before its first bad line is found; each
// is refused by what it is, before it is opened.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace skybake {

// "a directory", "a character device", "a block device", "a named pipe",
// "a socket", or nullptr for a regular file (or nothing at all).
const char* kindOfSpecialFile(const std::filesystem::file_status& status);

// Throws Error(BadInput) "<path>: <reason>" unless `path` is a regular file
// (a symbolic link to one counts) of at most `max_bytes`: no such file, a
// directory or special file ("is a named pipe, not a <what>"), larger than
// the cap, or a path holding a NUL character (which the system would cut
// it at). `what` names the kind of file ("config", "spectrum CSV", "bake
// file"). Returns the file's size.
std::uintmax_t requireInputFile(const std::filesystem::path& path, const std::string& what, std::uintmax_t max_bytes);

// requireInputFile, then the whole file.
std::string readInputFile(const std::filesystem::path& path, const std::string& what, std::uintmax_t max_bytes);

// Throws Error(BadInput) "<path>: contains a NUL character ..." for a path a
// caller took from text that may hold one (a Python str).
void requireNoNulInPath(const std::string& path);

}  // namespace skybake
