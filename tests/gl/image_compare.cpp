// Compares a GL render with the CPU render of the same view (linear EXR):
// the relative difference per pixel and channel over the values the CPU
// puts above a floor, its RMS and maximum, against the limits given.
// Usage: skybake_gl_image_compare CPU.exr GL.exr MAX_RMS MAX_ABS
// Prints "rms R max M over N values" and exits 1 past a limit, on a
// non-finite GL value or on differing image sizes.
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

// Radiance below this (W m^-2 sr^-1 nm^-1) is night sky or the space
// beyond the atmosphere, where a relative difference means nothing:
// 1e-5 is a millionth of the day sky and below 8-bit display at any
// exposure that shows the day.
constexpr double kRadianceFloor = 1e-5;

bool readImage(const char* path, std::vector<float>& pixels, int& width, int& height, int& channels) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return false;
  const OIIO::ImageSpec& spec = in->spec();
  width = spec.width;
  height = spec.height;
  channels = spec.nchannels;
  pixels.resize(static_cast<size_t>(width) * height * channels);
  return in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()) && in->close();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s CPU.exr GL.exr MAX_RMS MAX_ABS\n", argv[0]);
    return 2;
  }
  std::vector<float> cpu, gl;
  int w0 = 0, h0 = 0, c0 = 0, w1 = 0, h1 = 0, c1 = 0;
  if (!readImage(argv[1], cpu, w0, h0, c0) || !readImage(argv[2], gl, w1, h1, c1)) {
    std::fprintf(stderr, "cannot read %s or %s\n", argv[1], argv[2]);
    return 1;
  }
  if (w0 != w1 || h0 != h1 || c0 != c1) {
    std::printf("sizes differ: %dx%dx%d and %dx%dx%d\n", w0, h0, c0, w1, h1, c1);
    return 1;
  }
  double sum_squares = 0.0, largest = 0.0;
  size_t count = 0, non_finite = 0, worst = 0;
  for (size_t i = 0; i < cpu.size(); ++i) {
    if (!std::isfinite(gl[i])) ++non_finite;
    if (!(cpu[i] > kRadianceFloor)) continue;
    const double relative = std::abs(static_cast<double>(gl[i]) - cpu[i]) / cpu[i];
    sum_squares += relative * relative;
    if (relative > largest) largest = relative, worst = i;
    ++count;
  }
  const double rms = count > 0 ? std::sqrt(sum_squares / count) : 0.0;
  const size_t pixel = worst / c0;
  std::printf("rms %.4f %% max %.4f %% (pixel %zu,%zu channel %zu: cpu %g gl %g) over %zu values, %zu non-finite\n",
              rms * 100.0, largest * 100.0, pixel % w0, pixel / w0, worst % c0, cpu[worst], gl[worst], count,
              non_finite);
  const bool ok = count > 0 && non_finite == 0 && rms <= std::atof(argv[3]) && largest <= std::atof(argv[4]);
  return ok ? 0 : 1;
}
