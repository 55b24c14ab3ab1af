// Loads the image encoder module (image_encoder.h) on first use.
#include "baker/render/image_encoder.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>

#include <fmt/format.h>

#include "data_formats/error.h"

namespace skybake {
namespace {

using EncodeFunction = bool (*)(const ImageToEncode*, std::vector<unsigned char>*, std::string*);

constexpr const char* kModuleFileName = "libskybake_image_encoder.so";

// Where the module may be, in order: beside the program (the build tree),
// then the install's module folder relative to the program's
// (SKYBAKE_IMAGE_ENCODER_DIR, set by the build from the install layout).
std::vector<std::filesystem::path> moduleCandidates() {
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return {kModuleFileName};  // the loader's own search path
  const std::filesystem::path dir = program.parent_path();
  return {dir / kModuleFileName, dir / SKYBAKE_IMAGE_ENCODER_DIR / kModuleFileName};
}

EncodeFunction loadEncoder() {
  static std::once_flag once;
  static EncodeFunction encode = nullptr;
  static std::string failure;
  std::call_once(once, [] {
    for (const std::filesystem::path& candidate : moduleCandidates()) {
      void* module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (module == nullptr) {
        failure += fmt::format("{}{}", failure.empty() ? "" : "; ", dlerror());
        continue;
      }
      encode = reinterpret_cast<EncodeFunction>(dlsym(module, "skybake_encode_image"));
      if (encode != nullptr) return;
      failure += fmt::format("{}{}: no skybake_encode_image", failure.empty() ? "" : "; ", candidate.string());
    }
  });
  if (encode == nullptr) {
    throw Error(ErrorKind::Internal,
                fmt::format("cannot load the image encoder module ({}): {}", kModuleFileName, failure));
  }
  return encode;
}

}  // namespace

std::vector<unsigned char> encodeImage(const ImageToEncode& image) {
  const EncodeFunction encode = loadEncoder();
  std::vector<unsigned char> bytes;
  std::string error;
  if (!encode(&image, &bytes, &error)) throw Error(ErrorKind::Internal, fmt::format("{}: {}", image.path, error));
  return bytes;
}

}  // namespace skybake
