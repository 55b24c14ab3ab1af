// skybake render FILE.exr --altitude-m A --sun-zenith-deg Z [--sun-azimuth-deg P]
//   --projection fisheye|latlong|perspective [--fov-deg F] [--size WxH]
//   [--exposure E] [--tonemap none|reinhard|aces] [--channels rgb|spectral] [--no-sun]
//   [--backend cpu|gl] [--moon AZIMUTH,ELEVATION,ANGULAR_RADIUS] -o OUT.png|OUT.exr
#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "baker/cli/available_memory.h"
#include "baker/cli/commands.h"
#include "baker/cli/option_checks.h"
#include "baker/render/image_colour.h"
#include "baker/render/image_encoder.h"
#include "baker/render/render_request.h"
#include "baker/render/sky_image.h"
#include "baker/render/sun_disk_pixels.h"
#ifdef SKYBAKE_HAVE_GL
#include "baker/render/gl_sky_image.h"
#endif
#include "baker/validation/validation_queries.h"
#include "data_formats/atomic_file.h"
#include "data_formats/bake_file/bake_file.h"
#include "data_formats/error.h"
#include "runtime/colour/luminance.h"
#include "runtime/colour/srgb_primaries.h"

namespace skybake::cli {
namespace {

struct RenderOptions {
  std::string bake_path;
  std::string output_path;
  RenderRequest request;
  std::string size;  // WxH; empty: the projection's default
  double exposure = 10.0;
  std::string tone_map = "aces";
  std::string backend = "cpu";
  std::string channels = "rgb";
  bool no_sun = false;
  std::string moon;  // AZIMUTH,ELEVATION,ANGULAR_RADIUS in degrees; empty: none
};

const RenderRequestNames kOptionNames{"--altitude-m",         "--sun-zenith-deg",   "--sun-azimuth-deg",
                                      "--projection",         "--fov-deg",          "--size",
                                      "--view-elevation-deg", "--view-azimuth-deg", "--moon"};

// --moon AZIMUTH,ELEVATION,ANGULAR_RADIUS (degrees): three finite numbers
// (renderView checks their ranges).
std::array<double, 3> parseMoon(const std::string& text) {
  std::array<double, 3> values{};
  size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t comma = text.find(',', start);
    if ((i < 2) == (comma == std::string::npos)) {
      refuseOptionValue("--moon", text, "must be AZIMUTH,ELEVATION,ANGULAR_RADIUS in degrees, e.g. 0,40,0.28");
    }
    const std::string part = text.substr(start, i < 2 ? comma - start : std::string::npos);
    char* end = nullptr;
    values[i] = std::strtod(part.c_str(), &end);
    if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(values[i])) {
      refuseOptionValue("--moon", text, fmt::format("'{}' is not a finite number of degrees", part));
    }
    start = comma + 1;
  }
  return values;
}

// Radiance times exposure must stay within float range (3.4e38): the
// brightest radiance in an image, the sun's disk, is about 3e4
// W m^-2 sr^-1 nm^-1 for Earth's sun, leaving a factor of 1e4 to spare.
constexpr double kMaxExposure = 1e30;

// Memory per pixel while an image is rendered and written, per channel of
// the bake and per pixel: the spectral floats, and the encoded file in
// memory, at most about the spectral floats but in a vector that may have
// grown to twice that; besides them the linear sRGB floats and the
// tone-mapped bytes.
constexpr uint64_t kImageBytesPerPixelChannel = sizeof(float) + 2 * sizeof(float);
constexpr uint64_t kImageBytesPerPixel = 3 * sizeof(float) + 3;

void parseSize(const std::string& text, int& width, int& height) {
  const size_t x = text.find('x');
  const std::optional<long long> w = x == std::string::npos ? std::nullopt : parseWholeNumber(text.substr(0, x));
  const std::optional<long long> h = x == std::string::npos ? std::nullopt : parseWholeNumber(text.substr(x + 1));
  if (!w || !h) refuseOptionValue("--size", text, "must be WIDTHxHEIGHT in whole pixels, e.g. 512x512");
  if (*w < 1 || *h < 1 || *w > kMaxImageSide || *h > kMaxImageSide) {
    refuseOptionValue("--size", text, fmt::format("each side must be in [1, {}]", kMaxImageSide));
  }
  width = static_cast<int>(*w);
  height = static_cast<int>(*h);
}

// True for an .exr output, false for .png; refuses any other.
bool isExrOutput(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  const bool exr = extension == ".exr" || extension == ".EXR";
  if (!exr && extension != ".png" && extension != ".PNG") {
    throwBadInput(
        fmt::format("{}: output must be .png (tone-mapped sRGB) or .exr (linear sRGB or spectral radiance)", path));
  }
  return exr;
}

// The header attributes of an EXR image (data_formats/FORMAT.md, "Images"):
// its colour space and units, the bake's wavelengths, the camera and the
// sun, whether the sun disk is in the pixels or not.
std::vector<ImageAttribute> exrAttributes(const Sky& sky, const SkyView& view, bool spectral) {
  using Kind = ImageAttribute::Kind;
  std::vector<ImageAttribute> out;
  auto text = [&](const char* name, std::string value) { out.push_back({name, Kind::Text, std::move(value), {}, 0}); };
  auto number = [&](const char* name, double value) {
    out.push_back({name, Kind::Float, {}, {static_cast<float>(value)}, 0});
  };
  const std::vector<double>& wavelengths = sky.atmosphere().wavelengths_nm;
  if (spectral) {
    text("skybake:units", "W m^-2 sr^-1 nm^-1");
    text("skybake:content", "spectral radiance, one channel per wavelength of the bake, named after it (680nm)");
  } else {
    const colour::RgbChromaticities& c = colour::kSrgbChromaticities;
    out.push_back({"chromaticities",
                   Kind::Chromaticities,
                   {},
                   {static_cast<float>(c.red.x), static_cast<float>(c.red.y), static_cast<float>(c.green.x),
                    static_cast<float>(c.green.y), static_cast<float>(c.blue.x), static_cast<float>(c.blue.y),
                    static_cast<float>(c.white.x), static_cast<float>(c.white.y)},
                   0});
    // OpenEXR's whiteLuminance: the luminance, cd m^-2, of RGB (1, 1, 1).
    number("whiteLuminance", 1.0);
    text("skybake:units", "cd m^-2");
    text("skybake:content",
         sky.atmosphere().storesCieXyz()
             ? "linear sRGB (Rec. 709 primaries, D65 white) of the bake's CIE 1931 X, Y, Z (integrated "
               "at bake time over skybake:wavelengths_nm), in cd m^-2: Y = 0.2126 R + 0.7152 G + "
               "0.0722 B is luminance"
             : "linear sRGB (Rec. 709 primaries, D65 white) of spectral radiance through the CIE 1931 "
               "observer, in cd m^-2: Y = 0.2126 R + 0.7152 G + 0.0722 B is luminance");
  }
  text("skybake:wavelengths_nm", fmt::format("{}", fmt::join(wavelengths, " ")));
  text("skybake:bake_channels", sky.atmosphere().storesCieXyz() ? "cie_xyz" : "wavelengths");
  text("skybake:projection", view.projection == Projection::LatLong   ? "latlong"
                             : view.projection == Projection::Fisheye ? "fisheye"
                                                                      : "perspective");
  number("skybake:camera_altitude_m", view.altitude_m);
  const glm::dvec3 sun = sunDirection(view);
  out.push_back({"skybake:sun_direction",
                 Kind::Vector3,
                 {},
                 {static_cast<float>(sun.x), static_cast<float>(sun.y), static_cast<float>(sun.z)},
                 0});
  number("skybake:sun_zenith_deg", view.sun_zenith_deg);
  number("skybake:sun_azimuth_deg", view.sun_azimuth_deg);
  number("skybake:sun_angular_radius_rad", sky.atmosphere().sun_angular_radius_rad);
  out.push_back({"skybake:sun_in_image", Kind::Int, {}, {}, view.sun_disk ? 1 : 0});
  // The sun at the camera, on a surface facing it (the part the moon leaves),
  // every lane group's channels.
  const std::vector<float> irradiance = sky.everyChannel([&](const Sky& group) {
    return group.sunIrradiance(cameraPosition(group, view), sun, {sun, view.moon});
  });
  if (view.moon.present()) {
    const glm::dvec3 m = view.moon.centre_m;
    text("skybake:moon_centre_m", fmt::format("{} {} {}", m.x, m.y, m.z));
    number("skybake:moon_radius_m", view.moon.radius_m);
  }
  // Text, as the wavelengths: a float array would be stored as a v2f, a v3f
  // or a floatvector depending on the number of channels.
  // W m^-2 nm^-1 per wavelength; a colour bake's X, Y, Z in W m^-2.
  text("skybake:sun_irradiance_W_m2_nm", fmt::format("{}", fmt::join(irradiance, " ")));
  const SpectralImage sun_spectrum{1, 1, sky.channelCount(), irradiance};
  out.push_back({"skybake:sun_illuminance_rgb_lx",
                 Kind::Colour3,
                 {},
                 linearSrgbImage(sun_spectrum, sky.atmosphere(), colour::kMaxLuminousEfficacy_lm_per_W),
                 0});
  return out;
}

// Encodes the image in memory, then writes it out in one checked write: the
// PNG writer does not report a full disk (it leaves a short file and says it
// succeeded).
void writeImage(const std::string& path, const Sky& sky, const SkyView& view, const SpectralImage& image, bool spectral,
                double exposure, ToneMap tone_map) {
  const bool exr = isExrOutput(path);
  ImageToEncode encode;
  encode.path = path;
  encode.width = view.width;
  encode.height = view.height;
  encode.channels = spectral ? image.channels : 3;
  encode.float_pixels = exr;
  std::vector<float> rgb;
  std::vector<unsigned char> display;
  if (exr) {
    encode.compression = "zip";
    encode.attributes = exrAttributes(sky, view, spectral);
    if (spectral) {
      for (double w : sky.atmosphere().wavelengths_nm) encode.channel_names.push_back(channelName(w));
      encode.pixels = image.radiance.data();
    } else {
      rgb = linearSrgbImage(image, sky.atmosphere(), colour::kMaxLuminousEfficacy_lm_per_W);
      encode.pixels = rgb.data();
    }
  } else {
    encode.srgb = true;  // the PNG's sRGB chunk
    display = encodeForDisplay(linearSrgbImage(image, sky.atmosphere(), previewScalePerExposure()), exposure, tone_map);
    encode.pixels = display.data();
  }
  const std::vector<unsigned char> encoded = encodeImage(encode);
  writeFileContentsAtomically(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

// The image from the chosen backend. The GL context is made before the
// bake is read, so a machine without one is told so at once.
class ImageBackend {
 public:
  explicit ImageBackend(const std::string& backend) {
    if (backend != "cpu" && backend != "gl") refuseOptionValue("--backend", backend, "must be cpu or gl");
    if (backend == "cpu") return;
#ifdef SKYBAKE_HAVE_GL
    try {
      gl_.emplace();
    } catch (const Error& e) {
      refuseOptionValue("--backend", backend, e.what());
    }
#else
    refuseOptionValue("--backend", backend, "this skybake was built without OpenGL (libepoxy or EGL was not found)");
#endif
  }
  SpectralImage render(const Sky& sky, const SkyView& view) const {
#ifdef SKYBAKE_HAVE_GL
    if (gl_) return gl_->render(sky, view);
#endif
    return renderSkyRadiance(sky, view);
  }

 private:
#ifdef SKYBAKE_HAVE_GL
  std::optional<GlSkyImageRenderer> gl_;
#endif
};

void runRender(RenderOptions o) {
  const bool exr = isExrOutput(o.output_path);
  if (o.channels == "spectral" && !exr) {
    refuseOptionValue("--channels", o.channels, "needs an .exr output; a PNG shows sRGB");
  }
  RenderRequest& r = o.request;
  if (!o.moon.empty()) r.moon_deg = parseMoon(o.moon);
  if (!o.size.empty()) {
    int width = 0, height = 0;
    parseSize(o.size, width, height);
    r.size = std::array<int, 2>{width, height};
  }
  r.sun_disk = !o.no_sun;
  SkyView v = renderView(r, kOptionNames);
  const ImageBackend backend(o.backend);
  requireWritableOutput(o.output_path, {o.bake_path});
  const ToneMap tone_map = o.tone_map == "none"       ? ToneMap::None
                           : o.tone_map == "reinhard" ? ToneMap::Reinhard
                                                      : ToneMap::Aces;
  const Sky sky = Sky::load(o.bake_path);
  if (o.channels == "spectral" && sky.channels().kind == ChannelKind::CieXyz) {
    refuseOptionValue("--channels", o.channels,
                      fmt::format("{} is a colour bake: its channels are CIE X, Y, Z integrated at bake time, not "
                                  "wavelengths; render linear sRGB (--channels rgb), or bake with channels.store = "
                                  "\"wavelengths\" for spectral images",
                                  o.bake_path));
  }
  placeMoon(r, sky, v);
  requireMemoryAvailable(fmt::format("--size = {}x{}: the image", v.width, v.height),
                         static_cast<uint64_t>(v.width) * static_cast<uint64_t>(v.height) *
                             (kImageBytesPerPixel + kImageBytesPerPixelChannel * sky.channelCount()));
  const SpectralImage image =
      renderEveryChannel([&](const Sky& group, const SkyView& view) { return backend.render(group, view); }, sky, v);
  writeImage(o.output_path, sky, v, image, o.channels == "spectral", o.exposure, tone_map);
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render the sky of a bake as an image.");
  cmd->add_option("file", o->bake_path, "Bake file (.exr).")->required();
  cmd->add_option("-o,--output", o->output_path,
                  "Image: .png (tone-mapped sRGB) or .exr (linear sRGB in cd m^-2, Rec. 709 primaries and D65 "
                  "white in its chromaticities; or spectral radiance with --channels spectral).")
      ->required();
  requireFiniteIn(
      cmd->add_option("--altitude-m", o->request.altitude_m, "Camera altitude above the ground, m.")->required(),
      -kMaxQueryAltitude_m, kMaxQueryAltitude_m);
  requireFiniteIn(
      cmd->add_option("--sun-zenith-deg", o->request.sun_zenith_deg, "Sun zenith angle, degrees.")->required(), 0.0,
      kMaxZenithAngle_deg);
  requireFiniteIn(cmd->add_option("--sun-azimuth-deg", o->request.sun_azimuth_deg, "Sun azimuth, degrees (default 0)."),
                  -kMaxAzimuth_deg, kMaxAzimuth_deg);
  cmd->add_option("--projection", o->request.projection,
                  "fisheye (looking up), latlong (environment map) or perspective.")
      ->check(CLI::IsMember({"fisheye", "latlong", "perspective"}))
      ->capture_default_str();
  requireFiniteIn(cmd->add_option("--fov-deg", o->request.fov_deg,
                                  "Field of view, degrees (fisheye: full cone, default 180; perspective: "
                                  "horizontal, default 90)."),
                  kMinFieldOfView_deg, kMaxFieldOfView_deg);
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT (default 512x512, latlong 1024x512).");
  requirePositiveUpTo(
      cmd->add_option("--exposure", o->exposure,
                      "PNG only: multiplier on spectral radiance (W m^-2 sr^-1 nm^-1) before tone "
                      "mapping: a flat spectrum of 1 / E W m^-2 sr^-1 nm^-1 shows with Y = 1 before it.")
          ->capture_default_str(),
      kMaxExposure);
  cmd->add_option("--tonemap", o->tone_map, "Tone mapping for PNG: none, reinhard or aces.")
      ->check(CLI::IsMember({"none", "reinhard", "aces"}))
      ->capture_default_str();
  requireFiniteIn(cmd->add_option("--view-elevation-deg", o->request.view_elevation_deg,
                                  "Perspective: view elevation above the horizontal, degrees.")
                      ->capture_default_str(),
                  -90.0, 90.0);
  requireFiniteIn(cmd->add_option("--view-azimuth-deg", o->request.view_azimuth_deg,
                                  "Perspective: view azimuth, degrees (default: the sun's)."),
                  -kMaxAzimuth_deg, kMaxAzimuth_deg);
  cmd->add_option("--channels", o->channels,
                  "EXR only: rgb (linear sRGB, cd m^-2) or spectral (the bake's wavelengths as channels 680nm, "
                  "550nm, ..., W m^-2 sr^-1 nm^-1).")
      ->check(CLI::IsMember({"rgb", "spectral"}))
      ->capture_default_str();
  cmd->add_flag("--no-sun", o->no_sun,
                "Leave the sun disk out of the pixels (for a renderer that adds the sun as a directional light; an "
                "EXR's header still gives its direction and irradiance).");
  cmd->add_option("--backend", o->backend,
                  "cpu (the runtime's Sky lookups, all cores) or gl (the GLSL library of runtime/glsl on a headless "
                  "OpenGL 3.3 context: EGL, a GPU or Mesa's llvmpipe; float arithmetic, same images to within "
                  "0.5 % RMS).")
      ->capture_default_str();
  cmd->add_option("--moon", o->moon,
                  "A solar eclipse: the moon at AZIMUTH,ELEVATION,ANGULAR_RADIUS degrees (azimuth as "
                  "--sun-azimuth-deg's, elevation above the horizontal, seen from the camera at the mean lunar "
                  "distance), e.g. 0,40,0.28 before a sun at --sun-zenith-deg 50 for totality. It hides the sun "
                  "disk and shadows the sky (docs/ECLIPSES.md), with either backend.");
  return {cmd, [o] { runRender(*o); }};
}

}  // namespace skybake::cli
