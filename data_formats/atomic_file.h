// Writing an output so that a failure never leaves a partial file under the
// real name nor damages an existing one.
#pragma once

#include <filesystem>
#include <functional>

namespace skybake {

// Calls write(temp) with a temporary path beside `path` (same directory, so
// the final rename is atomic; same extension, so format-by-extension writers
// pick the right format), then renames temp onto path. If write throws or the
// rename fails, the temporary file is removed and Error(BadInput) names `path`
// and the reason (an Error thrown by write passes through unchanged).
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& temp)>& write);

}  // namespace skybake
