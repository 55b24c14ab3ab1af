// Bake file reader. Trusts nothing in the file: every part, channel, size and
// attribute is checked against the config carried in the header before a
// table is filled, and any OpenEXR failure becomes an Error naming the file.
#include <cmath>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>

#include "bake_file.h"
#include "bake_file_attributes.h"
#include "config.h"
#include "error.h"

namespace skybake {
namespace {

using namespace bake_file;

class Reader {
 public:
  explicit Reader(const std::filesystem::path& path) : path_(path.string()), file_(path_.c_str()) {}

  [[noreturn]] void fail(const std::string& what) const {
    throwBadInput(fmt::format("{}: {}", path_, what));
  }

  int findPart(const char* name) const {
    for (int i = 0; i < file_.parts(); ++i) {
      if (file_.header(i).hasName() && file_.header(i).name() == name) return i;
    }
    fail(fmt::format("part '{}' is missing", name));
  }

  const Imf::Header& header(int part) const { return file_.header(part); }

  template <typename Attribute>
  const Attribute& attribute(int part, const char* name) const {
    const Attribute* a = file_.header(part).findTypedAttribute<Attribute>(name);
    if (a == nullptr) fail(fmt::format("attribute {} is missing or of the wrong type", name));
    return *a;
  }

  // Reads a part of the expected size into `texels`.
  void readPart(const char* name, int width, int height, const AtmosphereParameters& a,
                std::vector<Spectrum>& texels) {
    const int part = findPart(name);
    const Imf::Header& h = file_.header(part);
    const Imath::Box2i window = h.dataWindow();
    const long long w = 1LL * window.max.x - window.min.x + 1;
    const long long ht = 1LL * window.max.y - window.min.y + 1;
    if (window.min.x != 0 || window.min.y != 0 || w != width || ht != height) {
      fail(fmt::format("part '{}' is {}x{} texels at ({}, {}); the config says {}x{} at (0, 0)",
                       name, w, ht, window.min.x, window.min.y, width, height));
    }
    texels.assign(static_cast<size_t>(width) * height, Spectrum(0.0f));
    Imf::FrameBuffer frame;
    char* base = reinterpret_cast<char*>(texels.data());
    for (int c = 0; c < a.channelCount(); ++c) {
      const std::string channel = channelName(a.wavelengths_nm[c]);
      if (h.channels().findChannel(channel) == nullptr) {
        fail(fmt::format("part '{}' has no channel {}", name, channel));
      }
      frame.insert(channel, Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(Spectrum),
                                       sizeof(Spectrum) * width));
    }
    Imf::InputPart in(file_, part);
    in.setFrameBuffer(frame);
    in.readPixels(0, height - 1);
    for (const Spectrum& s : texels) {
      for (int c = 0; c < a.channelCount(); ++c) {
        if (!std::isfinite(s[c])) fail(fmt::format("part '{}' holds a non-finite value", name));
      }
    }
  }

 private:
  std::string path_;
  Imf::MultiPartInputFile file_;
};

BakeFile readChecked(const std::filesystem::path& path) {
  Reader in(path);
  const int first = in.findPart(kPartScattering);
  const int version = in.attribute<Imf::IntAttribute>(first, kAttrFormatVersion).value();
  if (version != kBakeFormatVersion) {
    in.fail(fmt::format("format version {} is not understood by this skybake (it reads version {})",
                        version, kBakeFormatVersion));
  }
  BakeFile bake;
  bake.config = parseConfig(in.attribute<Imf::StringAttribute>(first, kAttrConfig).value(),
                            path.string() + " [" + kAttrConfig + "]");
  bake.orders_computed = in.attribute<Imf::IntAttribute>(first, kAttrOrders).value();
  bake.report_json = in.attribute<Imf::StringAttribute>(first, kAttrBakeReport).value();

  const TextureSizes& s = bake.config.sizes;
  const AtmosphereParameters& a = bake.config.atmosphere;
  BakeTables& t = bake.tables;
  t.transmittance = Texture2D(s.transmittance_mu, s.transmittance_r);
  in.readPart(kPartTransmittance, s.transmittance_mu, s.transmittance_r, a, t.transmittance.texels);
  t.irradiance = Texture2D(s.irradiance_mu_s, s.irradiance_r);
  in.readPart(kPartIrradiance, s.irradiance_mu_s, s.irradiance_r, a, t.irradiance.texels);
  t.scattering = Texture4D(s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu);
  in.readPart(kPartScattering, t.scattering.atlasWidth(), t.scattering.atlasHeight(), a,
              t.scattering.texels);
  t.single_mie = Texture4D(s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu);
  in.readPart(kPartSingleMie, t.single_mie.atlasWidth(), t.single_mie.atlasHeight(), a,
              t.single_mie.texels);
  t.multiple_density = Texture4D(s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu);
  in.readPart(kPartMultipleDensity, t.multiple_density.atlasWidth(), t.multiple_density.atlasHeight(), a,
              t.multiple_density.texels);
  return bake;
}

}  // namespace

BakeFile readBakeFile(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throwBadInput(fmt::format("{}: no such bake file", path.string()));
  }
  try {
    return readChecked(path);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    // OpenEXR reports truncated and corrupt files through its own exceptions.
    throwBadInput(fmt::format("{}: not a readable skybake bake file: {}", path.string(), e.what()));
  }
}

}  // namespace skybake
