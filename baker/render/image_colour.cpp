#include "baker/render/image_colour.h"

#include "runtime/colour/spectral_to_xyz.h"

namespace skybake {

std::vector<colour::LinearRgb> linearSrgbPerChannel(const AtmosphereParameters& channels, double scale) {
  std::vector<colour::LinearRgb> out;
  if (channels.storesCieXyz()) {
    for (const colour::Xyz& unit :
         {colour::Xyz{1.0, 0.0, 0.0}, colour::Xyz{0.0, 1.0, 0.0}, colour::Xyz{0.0, 0.0, 1.0}}) {
      out.push_back(colour::linearSrgbFromXyz(unit));
    }
  } else {
    const colour::SpectralToXyz to_xyz(channels.wavelengths_nm);
    for (int c = 0; c < to_xyz.channelCount(); ++c) out.push_back(colour::linearSrgbFromXyz(to_xyz.weight(c)));
  }
  for (colour::LinearRgb& rgb : out) rgb = {rgb.r * scale, rgb.g * scale, rgb.b * scale};
  return out;
}

std::vector<float> linearSrgbImage(const SpectralImage& image, const AtmosphereParameters& channels, double scale) {
  const std::vector<colour::LinearRgb> per_channel = linearSrgbPerChannel(channels, scale);
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  std::vector<float> rgb(pixels * 3);
  for (size_t p = 0; p < pixels; ++p) {
    const float* values = &image.radiance[p * image.channels];
    double r = 0.0, g = 0.0, b = 0.0;
    for (size_t c = 0; c < per_channel.size(); ++c) {
      r += per_channel[c].r * values[c];
      g += per_channel[c].g * values[c];
      b += per_channel[c].b * values[c];
    }
    rgb[p * 3 + 0] = static_cast<float>(r);
    rgb[p * 3 + 1] = static_cast<float>(g);
    rgb[p * 3 + 2] = static_cast<float>(b);
  }
  return rgb;
}

std::vector<float> linearSrgbImage(const SpectralImage& image, const std::vector<double>& wavelengths_nm,
                                   double scale) {
  AtmosphereParameters channels;
  channels.channel_kind = ChannelKind::Wavelengths;
  channels.wavelengths_nm = wavelengths_nm;
  return linearSrgbImage(image, channels, scale);
}

double previewScalePerExposure() { return 1.0 / colour::ybarIntegral_nm(); }

}  // namespace skybake
