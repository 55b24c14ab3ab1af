// Writing an output so that a failure never leaves a partial file under the
// real name nor damages an existing one.
//
// A failure to write an output (a missing or unwritable directory, a full
// disk, a file-size limit) is the user's to fix, like any other bad input:
// it throws Error(BadInput) naming the output and the system's reason.
#pragma once

#include <filesystem>
#include <functional>
#include <initializer_list>
#include <span>
#include <string_view>

namespace skybake {

// Refuses, before any work is done, an output path that cannot be written:
// empty, an existing directory, in a directory that does not exist, in one
// this process may not create files in, or the same file as one of the
// command's `inputs` (which the output would replace), a special file (a
// device, a pipe, a socket), a symbolic link to nothing, or a name whose
// temporary file's name would be too long for the file system, or a path
// holding a NUL character. Throws Error(BadInput) "<path>: <reason>".
void requireWritableOutput(const std::filesystem::path& path, std::initializer_list<std::filesystem::path> inputs = {});
// The same with the inputs in a list (a config and every file it names:
// BakeConfig::input_files).
void requireWritableOutput(const std::filesystem::path& path, std::span<const std::filesystem::path> inputs);

// Calls write(temp) with a temporary path beside `path` (same directory, so
// the final rename is atomic; same extension, so format-by-extension writers
// pick the right format), then renames temp onto path. If write throws or the
// rename fails, the temporary file is removed and Error(BadInput) names `path`
// and the reason (an Error thrown by write passes through unchanged). A
// symbolic link is written through (its target replaced, the link kept); a
// special file is refused. Temporary files of the same destination left by
// runs that were killed (whose process is gone) are removed first.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& temp)>& write);

// writeFileAtomically for contents already in memory (text or encoded
// bytes): every byte written and the file closed without error, or
// Error(BadInput) "<path>: cannot write: <system reason>" (e.g. "No space
// left on device"). Writers that do not report every failed write (libpng
// through OpenImageIO does not) encode to memory and write through this.
void writeFileContentsAtomically(const std::filesystem::path& path, std::string_view contents);

// The same for contents produced piece by piece: produce(emit) calls emit
// with each piece, in order; memory stays that of one buffer (1 MiB) however
// long the output.
void writeFileStreamAtomically(const std::filesystem::path& path,
                               const std::function<void(const std::function<void(std::string_view)>& emit)>& produce);

}  // namespace skybake
