#include "data_formats/input_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

#include "data_formats/error.h"

namespace skybake {

const char* kindOfSpecialFile(const std::filesystem::file_status& status) {
  switch (status.type()) {
    case std::filesystem::file_type::directory:
      return "a directory";
    case std::filesystem::file_type::character:
      return "a character device";
    case std::filesystem::file_type::block:
      return "a block device";
    case std::filesystem::file_type::fifo:
      return "a named pipe";
    case std::filesystem::file_type::socket:
      return "a socket";
    default:
      return nullptr;
  }
}

void requireNoNulInPath(const std::string& path) {
  const size_t nul = path.find('\0');
  if (nul != std::string::npos) {
    throwBadInput(fmt::format("{}\\0...: the path contains a NUL character, which ends a file name for the system",
                              path.substr(0, nul)));
  }
}

std::uintmax_t requireInputFile(const std::filesystem::path& path, const std::string& what, std::uintmax_t max_bytes) {
  const std::string name = path.string();
  requireNoNulInPath(name);
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throwBadInput(fmt::format("{}: no such {}", name, what));
  if (const char* kind = kindOfSpecialFile(status)) throwBadInput(fmt::format("{}: is {}, not a {}", name, kind, what));
  if (!std::filesystem::is_regular_file(status))
    throwBadInput(fmt::format("{}: not a regular file, not a {}", name, what));
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error) throwBadInput(fmt::format("{}: cannot read the file size: {}", name, error.message()));
  if (bytes > max_bytes) {
    throwBadInput(fmt::format("{}: {} bytes, larger than a {} can be ({} MiB)", name, bytes, what, max_bytes >> 20));
  }
  return bytes;
}

std::string readInputFile(const std::filesystem::path& path, const std::string& what, std::uintmax_t max_bytes) {
  const std::uintmax_t bytes = requireInputFile(path, what, max_bytes);
  std::ifstream file(path, std::ios::binary);
  if (!file) throwBadInput(fmt::format("{}: cannot open the {}: {}", path.string(), what, std::strerror(errno)));
  // One byte more than the size checked: a file that grew meanwhile (a log
  // being written) is refused after that many bytes, not read without end.
  std::string text(static_cast<size_t>(bytes) + 1, '\0');
  file.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(file.gcount()));
  if (text.size() > bytes) throwBadInput(fmt::format("{}: grew while it was read", path.string()));
  return text;
}

}  // namespace skybake
