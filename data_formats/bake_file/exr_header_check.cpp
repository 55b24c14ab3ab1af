// OpenEXRCore reads through callbacks: for a file it opens the file itself,
// for memory it reads from the caller's bytes. Its error messages go to the
// session rather than to stderr, and the first one names the reason.
#include "data_formats/bake_file/exr_header_check.h"

#include <algorithm>
#include <cstring>

#include <OpenEXR/openexr.h>
#include <fmt/format.h>

#include "data_formats/error.h"

namespace skybake {
namespace {

// What OpenEXRCore's callbacks share: the bytes for an in-memory file, and
// the detailed message of the first error (the result code alone is generic).
struct CoreSession {
  std::span<const std::byte> bytes;
  std::string message;
};

void keepFirstError(exr_const_context_t context, exr_result_t, const char* message) {
  void* user_data = nullptr;
  // A context that failed to come into being has no session to report to.
  if (exr_get_user_data(context, &user_data) != EXR_ERR_SUCCESS || user_data == nullptr) return;
  auto& s = *static_cast<CoreSession*>(user_data);
  if (s.message.empty() && message != nullptr) s.message = message;
}

int64_t readFromMemory(exr_const_context_t, void* user_data, void* buffer, uint64_t size, uint64_t offset,
                       exr_stream_error_func_ptr_t) {
  const std::span<const std::byte> bytes = static_cast<CoreSession*>(user_data)->bytes;
  if (offset >= bytes.size()) return 0;  // end of file, as pread reports it
  const uint64_t n = std::min<uint64_t>(size, bytes.size() - offset);
  std::memcpy(buffer, bytes.data() + offset, n);
  return static_cast<int64_t>(n);
}

int64_t memorySize(exr_const_context_t, void* user_data) {
  return static_cast<int64_t>(static_cast<CoreSession*>(user_data)->bytes.size());
}

// Parses the headers of `file_name`; `init` says where its bytes come from
// (OpenEXRCore opens the file by that name itself when it has no read function).
void parseHeaders(exr_context_initializer_t init, CoreSession& s, const std::string& file_name,
                  const std::string& source) {
  init.user_data = &s;
  init.error_handler_fn = keepFirstError;
  // Strict: an attribute whose declared size does not match its type is an
  // error, not something to skip over.
  init.flags |= EXR_CONTEXT_FLAG_STRICT_HEADER;
  exr_context_t context = nullptr;
  const exr_result_t result = exr_start_read(&context, file_name.c_str(), &init);
  exr_finish(&context);
  if (result != EXR_ERR_SUCCESS) {
    const std::string reason = exr_get_default_error_message(result);
    throwBadInput(fmt::format("{}: not a readable skybake bake file: OpenEXR header: {}", source,
                              s.message.empty() ? reason : fmt::format("{} ({})", s.message, reason)));
  }
}

}  // namespace

void checkExrHeaders(const std::filesystem::path& path, const std::string& source) {
  CoreSession s;
  parseHeaders(EXR_DEFAULT_CONTEXT_INITIALIZER, s, path.string(), source);
}

void checkExrHeaders(std::span<const std::byte> bytes, const std::string& source) {
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.read_fn = readFromMemory;
  init.size_fn = memorySize;
  CoreSession s{bytes, {}};
  parseHeaders(init, s, source, source);
}

}  // namespace skybake
