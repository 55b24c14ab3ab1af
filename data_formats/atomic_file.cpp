#include "atomic_file.h"

#include <unistd.h>

#include <fmt/format.h>

#include "error.h"

namespace skybake {

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& temp)>& write) {
  const std::filesystem::path temp =
      path.parent_path() /
      fmt::format(".{}.tmp-{}{}", path.stem().string(), ::getpid(), path.extension().string());
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
    throwBadInput(fmt::format("{}: cannot move the finished file into place: {}", path.string(),
                              error.message()));
  }
}

}  // namespace skybake
