// skybake render FILE.exr --altitude-m A --sun-zenith-deg Z [--sun-azimuth-deg P]
//   --projection fisheye|latlong|perspective [--fov-deg F] [--size WxH]
//   [--exposure E] [--tonemap none|reinhard|aces] -o OUT.png|OUT.exr
#include <optional>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include "baker/cli/commands.h"
#include "baker/render/sky_image.h"
#include "data_formats/atomic_file.h"
#include "data_formats/error.h"

namespace skybake::cli {
namespace {

struct RenderOptions {
  std::string bake_path;
  std::string output_path;
  SkyView view;
  std::string projection = "fisheye";
  double fov_deg = 0.0;  // 0: the projection's default
  std::string size;      // WxH; empty: the projection's default
  double exposure = 10.0;
  std::string tone_map = "aces";
  double view_elevation_deg = 10.0;
  std::optional<double> view_azimuth_deg;
};

// Largest image side: 16k pixels a side is far beyond any preview and keeps
// the float image under 3 GiB.
constexpr int kMaxImageSide = 16384;

void parseSize(const std::string& text, int& width, int& height) {
  const size_t x = text.find('x');
  int w = 0, h = 0;
  try {
    size_t used_w = 0, used_h = 0;
    if (x == std::string::npos) throw std::invalid_argument("no x");
    w = std::stoi(text.substr(0, x), &used_w);
    h = std::stoi(text.substr(x + 1), &used_h);
    if (used_w != x || used_h != text.size() - x - 1) throw std::invalid_argument("trailing");
  } catch (const std::exception&) {
    throwBadInput(fmt::format("--size {}: must be WIDTHxHEIGHT, e.g. 512x512", text));
  }
  if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide) {
    throwBadInput(fmt::format("--size {}: each side must be in [1, {}]", text, kMaxImageSide));
  }
  width = w;
  height = h;
}

void writeImage(const std::string& path, const SkyView& view, const std::vector<float>& linear,
                double exposure, ToneMap tone_map) {
  const std::string extension = std::filesystem::path(path).extension().string();
  const bool exr = extension == ".exr" || extension == ".EXR";
  if (!exr && extension != ".png" && extension != ".PNG") {
    throwBadInput(fmt::format("{}: output must be .png (tone-mapped sRGB) or .exr (linear radiance)", path));
  }
  writeFileAtomically(path, [&](const std::filesystem::path& temp) {
    auto out = OIIO::ImageOutput::create(temp.string());
    if (!out) throwBadInput(fmt::format("{}: cannot create image writer: {}", path, OIIO::geterror()));
    OIIO::ImageSpec spec(view.width, view.height, 3, exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (exr) spec.attribute("compression", "zip");
    if (!out->open(temp.string(), spec)) throwBadInput(fmt::format("{}: {}", path, out->geterror()));
    bool ok;
    if (exr) {
      ok = out->write_image(OIIO::TypeDesc::FLOAT, linear.data());
    } else {
      const std::vector<unsigned char> display = encodeForDisplay(linear, exposure, tone_map);
      ok = out->write_image(OIIO::TypeDesc::UINT8, display.data());
    }
    if (!ok || !out->close()) throwBadInput(fmt::format("{}: {}", path, out->geterror()));
  });
}

void runRender(RenderOptions o) {
  SkyView& v = o.view;
  v.projection = o.projection == "latlong"       ? Projection::LatLong
                 : o.projection == "perspective" ? Projection::Perspective
                                                 : Projection::Fisheye;
  v.fov_deg = o.fov_deg > 0.0 ? o.fov_deg : (v.projection == Projection::Perspective ? 90.0 : 180.0);
  if (v.projection == Projection::Perspective && v.fov_deg >= 179.0) {
    throwBadInput(fmt::format("--fov-deg {}: a perspective camera needs less than 179 degrees", v.fov_deg));
  }
  v.width = v.projection == Projection::LatLong ? 1024 : 512;
  v.height = 512;
  if (!o.size.empty()) parseSize(o.size, v.width, v.height);
  v.view_elevation_deg = o.view_elevation_deg;
  v.view_azimuth_deg = o.view_azimuth_deg.value_or(v.sun_azimuth_deg);
  const ToneMap tone_map = o.tone_map == "none" ? ToneMap::None : o.tone_map == "reinhard" ? ToneMap::Reinhard : ToneMap::Aces;
  const Sky sky = Sky::load(o.bake_path);
  writeImage(o.output_path, v, renderSkyRadiance(sky, v), o.exposure, tone_map);
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render the sky of a bake as an image.");
  cmd->add_option("file", o->bake_path, "Bake file (.exr).")->required();
  cmd->add_option("-o,--output", o->output_path, "Image: .png (tone-mapped sRGB, with the sun disk) or .exr (linear radiance, W m^-2 sr^-1 nm^-1).")->required();
  cmd->add_option("--altitude-m", o->view.altitude_m, "Camera altitude above the ground, m.")->required()
      ->check(kFiniteNumber)->check(CLI::Range(-1e12, 1e12));
  cmd->add_option("--sun-zenith-deg", o->view.sun_zenith_deg, "Sun zenith angle, degrees.")->required()
      ->check(kFiniteNumber)->check(CLI::Range(0.0, 180.0));
  cmd->add_option("--sun-azimuth-deg", o->view.sun_azimuth_deg, "Sun azimuth, degrees (default 0).")
      ->check(kFiniteNumber)->check(CLI::Range(-360.0, 360.0));
  cmd->add_option("--projection", o->projection, "fisheye (looking up), latlong (environment map) or perspective.")
      ->check(CLI::IsMember({"fisheye", "latlong", "perspective"}))->capture_default_str();
  cmd->add_option("--fov-deg", o->fov_deg, "Field of view, degrees (fisheye: full cone, default 180; perspective: horizontal, default 90).")
      ->check(kFiniteNumber)->check(CLI::Range(1.0, 360.0));
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT (default 512x512, latlong 1024x512).");
  cmd->add_option("--exposure", o->exposure, "Radiance multiplier before tone mapping (PNG only).")
      ->check(kFiniteNumber)->check(CLI::PositiveNumber)->capture_default_str();
  cmd->add_option("--tonemap", o->tone_map, "Tone mapping for PNG: none, reinhard or aces.")
      ->check(CLI::IsMember({"none", "reinhard", "aces"}))->capture_default_str();
  cmd->add_option("--view-elevation-deg", o->view_elevation_deg, "Perspective: view elevation above the horizontal, degrees.")
      ->check(kFiniteNumber)->check(CLI::Range(-90.0, 90.0))->capture_default_str();
  cmd->add_option("--view-azimuth-deg", o->view_azimuth_deg, "Perspective: view azimuth, degrees (default: the sun's).")
      ->check(kFiniteNumber);
  return {cmd, [o] { runRender(*o); }};
}

}  // namespace skybake::cli
