#include "baker/render/image_colour.h"

#include <span>

#include "runtime/colour/spectral_to_xyz.h"
#include "runtime/colour/srgb_primaries.h"

namespace skybake {

std::vector<float> linearSrgbImage(const SpectralImage& image, const std::vector<double>& wavelengths_nm,
                                   double scale) {
  const colour::SpectralToXyz to_xyz(wavelengths_nm);
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  std::vector<float> rgb(pixels * 3);
  for (size_t p = 0; p < pixels; ++p) {
    const std::span<const float> spectrum(&image.radiance[p * image.channels], static_cast<size_t>(image.channels));
    const colour::LinearRgb c = colour::linearSrgbFromXyz(to_xyz(spectrum));
    rgb[p * 3 + 0] = static_cast<float>(c.r * scale);
    rgb[p * 3 + 1] = static_cast<float>(c.g * scale);
    rgb[p * 3 + 2] = static_cast<float>(c.b * scale);
  }
  return rgb;
}

std::vector<float> linearSrgbImage(const SpectralImage& image, const AtmosphereParameters& channels, double scale) {
  if (!channels.storesCieXyz()) return linearSrgbImage(image, channels.wavelengths_nm, scale);
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  std::vector<float> rgb(pixels * 3);
  for (size_t p = 0; p < pixels; ++p) {
    const float* xyz = &image.radiance[p * image.channels];
    const colour::LinearRgb c = colour::linearSrgbFromXyz({xyz[0], xyz[1], xyz[2]});
    rgb[p * 3 + 0] = static_cast<float>(c.r * scale);
    rgb[p * 3 + 1] = static_cast<float>(c.g * scale);
    rgb[p * 3 + 2] = static_cast<float>(c.b * scale);
  }
  return rgb;
}

double previewScalePerExposure() { return 1.0 / colour::ybarIntegral_nm(); }

}  // namespace skybake
