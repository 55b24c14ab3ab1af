// Encoding a finished image (PNG or OpenEXR) into bytes in memory.
//
// OpenImageIO does the encoding, in a module of its own
// (libskybake_image_encoder.so) that skybake loads only when it writes an
// image: linked into the command, OpenImageIO and the hundreds of libraries
// it pulls in (codecs, OpenCV, GDAL) were loaded and initialised by every
// verb, 0.35 s before `skybake --help` could print.
#pragma once

#include <string>
#include <vector>

namespace skybake {

// A header attribute, typed as OpenEXR stores it.
struct ImageAttribute {
  enum class Kind { Text, Float, Int, Chromaticities, Vector3, Colour3 };
  std::string name;
  Kind kind = Kind::Text;
  std::string text;            // Kind::Text
  std::vector<float> numbers;  // Float: 1; Chromaticities: 8 (red, green, blue, white x and y); Vector3, Colour3: 3
  int integer = 0;             // Kind::Int
};

struct ImageToEncode {
  std::string path;  // its extension picks the format (.png, .exr)
  int width = 0;
  int height = 0;
  int channels = 0;
  bool float_pixels = false;               // 32-bit float (EXR) or 8-bit (PNG)
  const void* pixels = nullptr;            // width * height * channels values, rows top first
  std::vector<std::string> channel_names;  // empty: the format's defaults (R, G, B)
  bool srgb = false;                       // a PNG's sRGB chunk
  std::string compression;                 // e.g. "zip" for EXR; empty: the format's default
  std::vector<ImageAttribute> attributes;
};

// The encoded file's bytes. Throws Error(Internal) naming the path when the
// module cannot be loaded or the encoder fails.
std::vector<unsigned char> encodeImage(const ImageToEncode& image);

}  // namespace skybake

// The module's entry point (C linkage, looked up by name): fills `bytes`,
// or `error` and returns false.
extern "C" bool skybake_encode_image(const skybake::ImageToEncode* image, std::vector<unsigned char>* bytes,
                                     std::string* error);
