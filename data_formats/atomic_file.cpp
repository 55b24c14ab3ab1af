#include "atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "error.h"

namespace skybake {
namespace {

// The directory a file at `path` goes into ("." for a bare file name).
std::filesystem::path directoryOf(const std::filesystem::path& path) {
  return path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
}

// Writes all of `text` to the open descriptor; false with errno set if the
// system refuses part of it (a full disk, a file-size limit, an I/O error).
bool writeAll(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t written = ::write(fd, text.data(), text.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    text.remove_prefix(static_cast<size_t>(written));
  }
  return true;
}

}  // namespace

void requireWritableOutput(const std::filesystem::path& path, std::initializer_list<std::filesystem::path> inputs) {
  const std::string name = path.string();
  if (name.empty()) throwBadInput("output path is empty");
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throwBadInput(fmt::format("{}: is a directory; the output needs a file name", name));
  }
  const std::filesystem::path directory = directoryOf(path);
  const std::filesystem::file_status status = std::filesystem::status(directory, error);
  if (!std::filesystem::exists(status)) {
    throwBadInput(fmt::format("{}: output directory {} does not exist", name, directory.string()));
  }
  if (!std::filesystem::is_directory(status)) {
    throwBadInput(fmt::format("{}: {} is not a directory", name, directory.string()));
  }
  // Creating the temporary file and renaming it need write and search
  // permission on the directory; the existing file's own mode does not matter.
  if (::access(directory.c_str(), W_OK | X_OK) != 0) {
    throwBadInput(fmt::format("{}: cannot create files in {}: {}", name, directory.string(), std::strerror(errno)));
  }
  for (const std::filesystem::path& input : inputs) {
    if (!input.empty() && std::filesystem::equivalent(path, input, error)) {
      throwBadInput(fmt::format("{}: is also an input ({}); the output would replace it", name, input.string()));
    }
  }
}

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& temp)>& write) {
  const std::filesystem::path temp =
      path.parent_path() / fmt::format(".{}.tmp-{}{}", path.stem().string(), ::getpid(), path.extension().string());
  auto discard = [&] {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
  };
  try {
    write(temp);
  } catch (const Error&) {
    discard();
    throw;
  } catch (const std::exception& e) {
    discard();
    throwBadInput(fmt::format("{}: cannot write: {}", path.string(), e.what()));
  }
  std::error_code error;
  std::filesystem::rename(temp, path, error);
  if (error) {
    discard();
    throwBadInput(fmt::format("{}: cannot move the finished file into place: {}", path.string(), error.message()));
  }
}

void writeFileContentsAtomically(const std::filesystem::path& path, std::string_view contents) {
  writeFileAtomically(path, [&](const std::filesystem::path& temp) {
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throwBadInput(fmt::format("{}: cannot write: {}", path.string(), std::strerror(errno)));
    const bool written = writeAll(fd, contents);
    const int write_errno = errno;
    // close reports errors some file systems (NFS) only find at the end.
    const bool closed = ::close(fd) == 0;
    if (!written || !closed) {
      throwBadInput(fmt::format("{}: cannot write: {}", path.string(), std::strerror(written ? errno : write_errno)));
    }
  });
}

}  // namespace skybake
