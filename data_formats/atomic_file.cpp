#include "data_formats/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "data_formats/error.h"
#include "data_formats/input_file.h"

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

// The temporary file an output is written to before its rename: hidden,
// beside the destination, named for the destination and this process.
std::string temporaryName(const std::filesystem::path& path, long pid) {
  return fmt::format(".{}.tmp-{}{}", path.stem().string(), pid, path.extension().string());
}

// Where an output really goes: a symbolic link is written through (its
// target replaced, the link kept), so that a link into another directory
// stays a link. Special files are refused: the atomic rename would replace
// a device node or a pipe with a regular file.
std::filesystem::path outputDestination(const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::path destination = path;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, error))) {
    destination = std::filesystem::weakly_canonical(path, error);
    if (error || !std::filesystem::exists(destination, error)) {
      throwBadInput(
          fmt::format("{}: is a symbolic link to a missing file; write to its target or remove it", path.string()));
    }
  }
  if (const char* kind = kindOfSpecialFile(std::filesystem::status(destination, error))) {
    throwBadInput(
        fmt::format("{}: is {}, not a regular file; skybake writes each output as a regular file, "
                    "renamed into place",
                    path.string(), kind));
  }
  return destination;
}

bool processIsAlive(long pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

// Removes the temporary files an earlier run writing `destination` left when
// it was killed (its process no longer exists): they are named
// temporaryName(destination, its pid).
void removeStaleTemporaries(const std::filesystem::path& destination) {
  const std::string prefix = fmt::format(".{}.tmp-", destination.stem().string());
  const std::string extension = destination.extension().string();
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directoryOf(destination), error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= prefix.size() + extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - extension.size(), extension.size(), extension) != 0) {
      continue;
    }
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    const long pid = std::stol(digits);
    if (pid == ::getpid() || processIsAlive(pid)) continue;
    std::error_code ignored;
    std::filesystem::remove(entry.path(), ignored);
  }
}

}  // namespace

void requireWritableOutput(const std::filesystem::path& path, std::initializer_list<std::filesystem::path> inputs) {
  requireWritableOutput(path, std::span<const std::filesystem::path>(inputs.begin(), inputs.size()));
}

void requireWritableOutput(const std::filesystem::path& path, std::span<const std::filesystem::path> inputs) {
  const std::string name = path.string();
  if (name.empty()) throwBadInput("output path is empty");
  requireNoNulInPath(name);
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throwBadInput(fmt::format("{}: is a directory; the output needs a file name", name));
  }
  const std::filesystem::path destination = outputDestination(path);
  const std::filesystem::path directory = directoryOf(destination);
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
  // The temporary name is longer than the output's: refused now rather
  // than after the work. A process id has at most 7 digits on Linux.
  const std::string temp_name = temporaryName(destination, 9999999);
  const long name_max = ::pathconf(directory.c_str(), _PC_NAME_MAX);
  if (name_max > 0 && static_cast<long>(temp_name.size()) > name_max) {
    throwBadInput(
        fmt::format("{}: the file name is too long: its temporary file's name ({} bytes) would exceed "
                    "the {} bytes the file system allows",
                    name, temp_name.size(), name_max));
  }
  for (const std::filesystem::path& input : inputs) {
    if (!input.empty() && std::filesystem::equivalent(path, input, error)) {
      throwBadInput(fmt::format("{}: is also an input ({}); the output would replace it", name, input.string()));
    }
  }
}

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& temp)>& write) {
  const std::filesystem::path destination = outputDestination(path);
  removeStaleTemporaries(destination);
  const std::filesystem::path temp = destination.parent_path() / temporaryName(destination, ::getpid());
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
  std::filesystem::rename(temp, destination, error);
  if (error) {
    discard();
    throwBadInput(fmt::format("{}: cannot move the finished file into place: {}", path.string(), error.message()));
  }
}

void writeFileStreamAtomically(const std::filesystem::path& path,
                               const std::function<void(const std::function<void(std::string_view)>& emit)>& produce) {
  // Pieces are gathered up to this size before each write: one system call
  // per line of a ten-million-line output would dominate its time.
  constexpr size_t kBufferBytes = 1 << 20;
  writeFileAtomically(path, [&](const std::filesystem::path& temp) {
    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throwBadInput(fmt::format("{}: cannot write: {}", path.string(), std::strerror(errno)));
    // Closed on every way out; an error closing it is reported below.
    struct Closer {
      int& fd;
      ~Closer() {
        if (fd >= 0) ::close(fd);
      }
    } closer{fd};
    std::string buffer;
    buffer.reserve(kBufferBytes);
    auto flush = [&] {
      if (!writeAll(fd, buffer))
        throwBadInput(fmt::format("{}: cannot write: {}", path.string(), std::strerror(errno)));
      buffer.clear();
    };
    produce([&](std::string_view piece) {
      buffer.append(piece);
      if (buffer.size() >= kBufferBytes) flush();
    });
    flush();
    // close reports errors some file systems (NFS) only find at the end.
    const int closed = ::close(fd);
    fd = -1;
    if (closed != 0) throwBadInput(fmt::format("{}: cannot write: {}", path.string(), std::strerror(errno)));
  });
}

void writeFileContentsAtomically(const std::filesystem::path& path, std::string_view contents) {
  writeFileStreamAtomically(path, [&](const std::function<void(std::string_view)>& emit) { emit(contents); });
}

}  // namespace skybake
