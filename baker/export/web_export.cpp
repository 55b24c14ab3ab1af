#include "baker/export/web_export.h"

#include <zlib.h>

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "baker/render/image_colour.h"
#include "data_formats/bake_file/bake_file.h"
#include "data_formats/error.h"
#include "runtime/colour/luminance.h"
#include "runtime/gl/sky_gl_parameters.h"
#include "runtime/gl/sky_gpu_textures.h"

namespace skybake {
namespace {

// zlib's level: 6, its default, compresses the half tables within a few
// percent of 9 at about a third of the time.
constexpr int kGzipLevel = 6;
// windowBits for deflateInit2: 15 (a 32 KiB window) plus 16 for a gzip
// wrapper, which browsers' DecompressionStream("gzip") reads. The header's
// time stamp is 0, so an export's bytes depend on the bake alone.
constexpr int kGzipWindowBits = 15 + 16;
constexpr int kGzipMemoryLevel = 8;

std::string gzip(std::span<const std::byte> bytes) {
  z_stream stream{};
  if (deflateInit2(&stream, kGzipLevel, Z_DEFLATED, kGzipWindowBits, kGzipMemoryLevel, Z_DEFAULT_STRATEGY) != Z_OK) {
    throw Error(ErrorKind::Internal, "zlib: deflateInit2 failed");
  }
  std::string out(deflateBound(&stream, bytes.size()), '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&stream, Z_FINISH);
  out.resize(stream.total_out);
  deflateEnd(&stream);
  if (status != Z_STREAM_END) throw Error(ErrorKind::Internal, "zlib: deflate did not finish");
  return out;
}

// The uniform block's members in order, named and typed as the GLSL
// declares them (runtime/glsl/skybake_uniform_block.inc).
struct BlockMember {
  const char* name;
  bool integer;
  int count;
  size_t offset;
};
const std::vector<BlockMember>& blockMembers() {
  using gl::SkyUniformBlock;
  static const std::vector<BlockMember> members = {
#define SKYBAKE_MAX_DENSITY_LAYERS gl::kMaxGlDensityLayers
#define SKYBAKE_MAX_INTEGRAL_PASSES gl::kMaxGlIntegralPasses
#define SKYBAKE_BLOCK_MEMBER(type, name) \
  {"skybake_" #name, std::string_view(#type) == "ivec4", 1, offsetof(SkyUniformBlock, name)},
#define SKYBAKE_BLOCK_ARRAY(type, name, count) \
  {"skybake_" #name, std::string_view(#type) == "ivec4", count, offsetof(SkyUniformBlock, name)},
#include "runtime/glsl/skybake_uniform_block.inc"
#undef SKYBAKE_BLOCK_ARRAY
#undef SKYBAKE_BLOCK_MEMBER
#undef SKYBAKE_MAX_INTEGRAL_PASSES
#undef SKYBAKE_MAX_DENSITY_LAYERS
  };
  return members;
}

nlohmann::ordered_json uniformBlockJson(const gl::SkyUniformBlock& block) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(&block);
  nlohmann::ordered_json members = nlohmann::ordered_json::array();
  for (const BlockMember& m : blockMembers()) {
    nlohmann::ordered_json values = nlohmann::ordered_json::array();
    for (int i = 0; i < 4 * m.count; ++i) {
      const unsigned char* at = bytes + m.offset + 4 * static_cast<size_t>(i);
      if (m.integer) {
        std::int32_t v = 0;
        std::memcpy(&v, at, sizeof(v));
        values.push_back(v);
      } else {
        float v = 0.0f;
        std::memcpy(&v, at, sizeof(v));
        values.push_back(v);
      }
    }
    members.push_back(
        {{"name", m.name}, {"type", m.integer ? "ivec4" : "vec4"}, {"count", m.count}, {"values", values}});
  }
  return {{"name", gl::kSkyUniformBlockName}, {"bytes", sizeof(gl::SkyUniformBlock)}, {"members", members}};
}

// WebGL2's names for a texel format: internal format, format, type.
std::array<const char*, 3> webGlFormat(gl::GpuTexelFormat format) {
  switch (format) {
    case gl::GpuTexelFormat::Rgb16f:
      return {"RGB16F", "RGB", "HALF_FLOAT"};
    case gl::GpuTexelFormat::Rgba16f:
      return {"RGBA16F", "RGBA", "HALF_FLOAT"};
    case gl::GpuTexelFormat::Rgba32f:
      break;
  }
  return {"RGBA32F", "RGBA", "FLOAT"};
}

// What a sampler's name says without its prefix: skybake_optical_depth ->
// optical_depth.
std::string tableName(const char* sampler) { return std::string(sampler).substr(std::strlen("skybake_")); }

// validate's errors (report sidecar, "validation") as a viewer shows them.
nlohmann::ordered_json validationFacts(const nlohmann::ordered_json& validation) {
  nlohmann::ordered_json errors = nlohmann::ordered_json::array();
  for (const auto& e : validation.at("errors")) {
    if (!e.is_object() || !e.contains("channels") || !e["channels"].is_array()) continue;
    double rms = 0.0, p95 = 0.0, max = 0.0;
    int count = 0;
    for (const auto& ch : e["channels"]) {
      if (!ch.is_object() || !ch.value("count", 0)) continue;
      count += ch.value("count", 0);
      rms = std::max(rms, ch.value("rms", 0.0));
      p95 = std::max(p95, ch.value("p95", 0.0));
      max = std::max(max, ch.value("max", 0.0));
    }
    if (count == 0) continue;
    errors.push_back({{"quantity", e.value("quantity", "")},
                      {"band", e.value("band", "")},
                      {"rms_percent", 100.0 * rms},
                      {"p95_percent", 100.0 * p95},
                      {"max_percent", 100.0 * max}});
  }
  return {{"query_set", validation.value("query_set", "")}, {"errors", errors}};
}

}  // namespace

std::vector<WebFile> webExport(const Sky& sky, const nlohmann::ordered_json& facts, WebTableEncoding encoding) {
  const AtmosphereParameters& a = sky.atmosphere();
  const bool xyz = a.storesCieXyz();
  // Linear sRGB per unit of each channel at render's preview scale, so
  // that a viewer's exposure means `skybake render --exposure`'s.
  const std::vector<colour::LinearRgb> preview_rgb = linearSrgbPerChannel(a, previewScalePerExposure());
  const std::vector<float>& luminance_weights = sky.channelLuminanceWeights();

  std::vector<WebFile> files;
  std::vector<std::vector<gl::GpuTexture>> group_textures(static_cast<size_t>(sky.laneGroupCount()));
  for (int g = 0; g < sky.laneGroupCount(); ++g) {
    group_textures[g] = gl::skyGpuTextures(sky.laneGroup(g), GpuTablePrecision::Half);
  }
  // Packed in parallel: gzip of the half tables is most of an export's time.
  const bool gzipped = encoding == WebTableEncoding::Gzip;
  const size_t per_group = gl::kSkySamplerNames.size();
  std::vector<std::string> table_files(group_textures.size() * per_group);
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < static_cast<int>(table_files.size()); ++i) {
    const std::span<const std::byte> bytes = group_textures[i / per_group][i % per_group].bytes();
    table_files[i] = gzipped ? gzip(bytes) : std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }

  nlohmann::ordered_json group_json = nlohmann::ordered_json::array();
  for (int g = 0; g < sky.laneGroupCount(); ++g) {
    const Sky& group = sky.laneGroup(g);
    const int first = sky.laneGroupFirstChannel(g);
    nlohmann::ordered_json lanes = nlohmann::ordered_json::array();
    nlohmann::ordered_json textures = nlohmann::ordered_json::array();
    for (int lane = 0; lane < group.channelCount(); ++lane) {
      const colour::LinearRgb& rgb = preview_rgb[static_cast<size_t>(first + lane)];
      lanes.push_back({{"channel", first + lane},
                       {"preview_linear_srgb", {rgb.r, rgb.g, rgb.b}},
                       {"luminance_cd_m2", luminance_weights[static_cast<size_t>(first + lane)]}});
    }
    for (size_t t = 0; t < per_group; ++t) {
      const gl::GpuTexture& texture = group_textures[g][t];
      const std::string name = fmt::format("group{}_{}.bin{}", g, tableName(texture.sampler), gzipped ? ".gz" : "");
      const std::array<const char*, 3> format = webGlFormat(texture.format);
      textures.push_back({{"sampler", texture.sampler},
                          {"file", name},
                          {"encoding", gzipped ? "gzip" : "none"},
                          {"target", texture.dimensions == 2 ? "TEXTURE_2D" : "TEXTURE_3D"},
                          {"size", {texture.width, texture.height, texture.depth}},
                          {"internal_format", format[0]},
                          {"format", format[1]},
                          {"type", format[2]},
                          {"bytes", texture.bytes().size()}});
      files.push_back(
          {name, gzipped ? "application/gzip" : "application/octet-stream", std::move(table_files[g * per_group + t])});
    }
    group_json.push_back({{"first_channel", first},
                          {"lanes", lanes},
                          {"uniform_block", uniformBlockJson(gl::skyUniformBlock(group))},
                          {"textures", textures}});
  }
  files.push_back({"skybake.glsl", "text/plain; charset=utf-8", gl::skyGlslLibrary()});

  const nlohmann::ordered_json manifest = {
      {"format", kWebExportFormat},
      {"version", kWebExportVersion},
      {"channels",
       {{"kind", xyz ? "cie_xyz" : "wavelengths"},
        {"names", channelNames(a)},
        {"wavelengths_nm", a.wavelengths_nm},
        {"unit", xyz ? "W m^-2 sr^-1" : "W m^-2 sr^-1 nm^-1"}}},
      {"glsl",
       {{"file", "skybake.glsl"},
        {"es_header",
         "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
         "precision highp sampler3D;\n"}}},
      {"preview",
       {{"exposure", "display = tone_map(exposure * sum over lanes of preview_linear_srgb * value), sRGB-encoded"},
        {"cd_m2_per_preview_unit", colour::kMaxLuminousEfficacy_lm_per_W / previewScalePerExposure()}}},
      {"groups", group_json},
      {"facts", facts}};
  files.push_back({kWebManifestName, "application/json", manifest.dump(1) + "\n"});
  return files;
}

nlohmann::ordered_json bakeFacts(const Sky& sky, const std::string& file_name, int format_version,
                                 const std::string& atmosphere_name, const nlohmann::ordered_json& sidecar) {
  const BakeContents& c = sky.contents();
  const TextureSizes& s = c.sizes;
  nlohmann::ordered_json facts = {
      {"file", file_name},
      {"format_version", format_version},
      {"atmosphere", atmosphere_name},
      {"bottom_radius_m", c.atmosphere.bottom_radius_m},
      {"top_radius_m", c.atmosphere.top_radius_m},
      {"orders", sky.orders()},
      {"optical_depth_size", {s.transmittance_mu, s.transmittance_r}},
      {"irradiance_size", {s.irradiance_mu_s, s.irradiance_r}},
      {"scattering_size", {s.scattering_r, s.scattering_mu, s.scattering_mu_s, s.scattering_nu}},
      {"outputs",
       {{"radiance_to_points", c.outputs.radiance_to_points}, {"ground_irradiance", c.outputs.ground_irradiance}}}};
  // The validated errors: per quantity and sun band, the worst channel's
  // relative RMS, 95th percentile and maximum, in percent. A sidecar that
  // does not hold them as validate writes them adds nothing.
  const auto validation = sidecar.is_object() ? sidecar.find("validation") : sidecar.end();
  if (validation == sidecar.end() || !validation->is_object() || !validation->contains("errors")) return facts;
  try {
    facts["validation"] = validationFacts(*validation);
  } catch (const nlohmann::json::exception&) {
    // A value of another type than validate writes: the facts go without it.
  }
  return facts;
}

}  // namespace skybake
