// The image encoder module (image_encoder.h): OpenImageIO, loaded on demand.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "baker/render/image_encoder.h"

namespace {

void addAttribute(OIIO::ImageSpec& spec, const skybake::ImageAttribute& a) {
  using Kind = skybake::ImageAttribute::Kind;
  switch (a.kind) {
    case Kind::Text:
      spec.attribute(a.name, a.text);
      break;
    case Kind::Float:
      spec.attribute(a.name, a.numbers.at(0));
      break;
    case Kind::Int:
      spec.attribute(a.name, a.integer);
      break;
    case Kind::Chromaticities:
      spec.attribute(a.name, OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), a.numbers.data());
      break;
    case Kind::Vector3:
      spec.attribute(a.name, OIIO::TypeVector, a.numbers.data());
      break;
    case Kind::Colour3:
      spec.attribute(a.name, OIIO::TypeColor, a.numbers.data());
      break;
  }
}

}  // namespace

extern "C" __attribute__((visibility("default"))) bool skybake_encode_image(const skybake::ImageToEncode* image,
                                                                            std::vector<unsigned char>* bytes,
                                                                            std::string* error) {
  try {
    OIIO::Filesystem::IOVecOutput memory(*bytes);
    auto out = OIIO::ImageOutput::create(image->path, &memory);
    if (!out || !out->supports("ioproxy")) {
      *error = "no in-memory image writer: " + OIIO::geterror();
      return false;
    }
    const OIIO::TypeDesc type = image->float_pixels ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(image->width, image->height, image->channels, type);
    if (!image->compression.empty()) spec.attribute("compression", image->compression);
    if (image->srgb) spec.attribute("oiio:ColorSpace", "sRGB");
    for (const skybake::ImageAttribute& a : image->attributes) addAttribute(spec, a);
    if (!image->channel_names.empty()) spec.channelnames = image->channel_names;
    const bool ok = out->set_ioproxy(&memory) && out->open(image->path, spec) &&
                    out->write_image(type, image->pixels) && out->close();
    if (!ok) *error = out->geterror();
    return ok;
  } catch (const std::exception& e) {
    *error = e.what();
    return false;
  }
}
