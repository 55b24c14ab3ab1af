// The GLSL library's lookups equal skybake::Sky's: sky radiance (with light
// shafts), radiance to a point (aerial perspective), irradiance and
// transmittance, evaluated for the same queries on a headless OpenGL
// context and on the CPU, and finite for hostile geometry.
//
// Tolerance: RMS relative difference <= 0.5 %, max <= 2 %, over values
// above 1e-5 (W m^-2 sr^-1 nm^-1, or W m^-2 nm^-1, or transmittance). The
// GLSL computes in float where the CPU computes coordinates and sums in
// double: float resolves a planet-sized radius to half a metre, which
// moves a texture coordinate by up to 1e-3 of a texel near the ground and
// more along rays that graze the horizon, where the tables change fastest;
// quadrature sums of 16 to 64 float terms add 1e-6 each. Interpolation is
// done in the shader from texelFetch with the CPU's weights (hardware
// filtering has 8 bits of sub-texel weight, 0.4 % of a texel-to-texel step,
// more than the whole budget where neighbouring texels differ tenfold in
// twilight). The 2 % maximum leaves room for the few queries within float
// resolution of a discontinuity (a ray that grazes the ground is classified
// by a sign the float and double arithmetic can disagree on).
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "data_formats/error.h"
#include "runtime/gl/gl_program.h"
#include "runtime/gl/headless_gl_context.h"
#include "runtime/gl/sky_gl_parameters.h"
#include "runtime/gl/sky_gl_resources.h"
#include "runtime/gl/sky_gpu_textures.h"
#include "runtime/sky.h"

namespace skybake {
namespace {

// Query kinds, as the shader below reads them.
enum class Kind {
  SkyRadiance = 0,
  RadianceToPoint = 1,
  Irradiance = 2,
  Transmittance = 3,
  Received = 4,
  Luminance = 5,
  EclipseSkyRadiance = 6,
  EclipseReceived = 7,
  EclipseIrradiance = 8,
  EclipseSkylightAndSun = 9,
  EclipseSun = 10,
  EclipseRadianceToPoint = 11
};

struct Query {
  Kind kind;
  glm::vec3 a;  // camera or point, m
  glm::vec3 b;  // view direction, point or normal
  glm::vec3 sun;
  float shadow_length_m = 0.0f;
  glm::vec4 moon{0.0f};  // a solar eclipse's moon: centre (m), radius (m); radius 0: none
};

// Each pixel evaluates one query; two outputs (radiance and transmittance,
// or sun and sky irradiance). The plain lookups and the eclipse lookups are
// two programs: llvmpipe compiles every lookup a shader calls, and the
// eclipse lookups alone take it tens of seconds.
const char* const kQueryInputs = R"(
uniform sampler2D query_a;  // xyz, w shadow length
uniform sampler2D query_b;  // xyz
uniform sampler2D query_c;  // xyz sun, w kind
uniform sampler2D query_d;  // moon: xyz centre, w radius
layout(location = 0) out vec4 first;
layout(location = 1) out vec4 second;
// The pixel's query input.
vec4 queryInput(sampler2D query) { return texelFetch(query, ivec2(gl_FragCoord.xy), 0); }
)";

const char* const kQueryMain = R"(
void main() {
  vec4 qa = queryInput(query_a);
  vec4 qb = queryInput(query_b);
  vec4 qc = queryInput(query_c);
  int kind = int(qc.w);
  first = vec4(0.0);
  second = vec4(0.0);
  if (kind == 0) {
    SkybakeRadianceAndTransmittance v = skybakeSkyRadiance(qa.xyz, qb.xyz, qc.xyz, qa.w);
    first = v.radiance;
    second = v.transmittance;
  } else if (kind == 1) {
    SkybakeRadianceAndTransmittance v = skybakeRadianceToPoint(qa.xyz, qb.xyz, qc.xyz, qa.w);
    first = v.radiance;
    second = v.transmittance;
  } else if (kind == 2) {
    SkybakeSunAndSkyIrradiance e = skybakeSunAndSkyIrradiance(qa.xyz, qb.xyz, qc.xyz);
    first = e.sun;
    second = e.sky;
  } else if (kind == 3) {
    first = skybakeTransmittance(qa.xyz, qb.xyz);
  } else if (kind == 5) {
    // The luminance of the sky radiance, and what the bake's channels hold.
    SkybakeRadianceAndTransmittance v = skybakeSkyRadiance(qa.xyz, qb.xyz, qc.xyz, qa.w);
    first = vec4(skybakeLuminance(v.radiance), skybakeChannelsAreCieXyz() ? 1.0 : 0.0, 0.0, 0.0);
  } else {
    SkybakeRadianceAndTransmittance v = skybakeReceivedRadiance(qa.xyz, qb.xyz, qc.xyz);
    first = v.radiance;
    second = v.transmittance;
  }
}
)";

const char* const kEclipseQueryMain = R"(
void main() {
  vec4 qa = queryInput(query_a);
  vec4 qb = queryInput(query_b);
  vec4 qc = queryInput(query_c);
  vec4 qd = queryInput(query_d);
  SkybakeMoon moon = SkybakeMoon(qd.xyz, qd.w);
  int kind = int(qc.w);
  first = vec4(0.0);
  second = vec4(0.0);
  if (kind == 6) {
    SkybakeRadianceAndTransmittance v = skybakeSkyRadiance(qa.xyz, qb.xyz, qc.xyz, moon);
    first = v.radiance;
    second = v.transmittance;
  } else if (kind == 7) {
    SkybakeRadianceAndTransmittance v = skybakeReceivedRadiance(qa.xyz, qb.xyz, qc.xyz, moon);
    first = v.radiance;
    second = v.transmittance;
  } else if (kind == 8) {
    SkybakeSunAndSkyIrradiance e = skybakeSunAndSkyIrradiance(qa.xyz, qb.xyz, qc.xyz, moon);
    first = e.sun;
    second = e.sky;
  } else if (kind == 11) {
    SkybakeRadianceAndTransmittance v = skybakeRadianceToPoint(qa.xyz, qb.xyz, qc.xyz, moon);
    first = v.radiance;
    second = v.transmittance;
  } else {
    // The skylight share at a point (kind 9 only), the sun's visible
    // fraction there, and whether the view direction from it sees the sun
    // disk past the moon.
    if (kind == 9) first = skybakeEclipseSkylight(qa.xyz, qc.xyz, moon);
    second = vec4(skybakeMoonVisibleSunFraction(moon, qa.xyz, qc.xyz, skybake_sun_disk.x),
                  skybakeInSunDiskPastMoon(qa.xyz, qb.xyz, qc.xyz, moon) ? 1.0 : 0.0, 0.0, 0.0);
  }
}
)";

// The sky from cameras in the atmosphere only, for a program that leaves
// out what those lookups never use by day (runtime/glsl/README.md).
const char* const kDaylightQueryMain = R"(
void main() {
  vec4 qa = queryInput(query_a);
  vec4 qb = queryInput(query_b);
  vec4 qc = queryInput(query_c);
  SkybakeRadianceAndTransmittance v;
  if (int(qc.w) == 0) {
    v = skybakeSkyRadiance(qa.xyz, qb.xyz, qc.xyz);
  } else {
    v = skybakeReceivedRadiance(qa.xyz, qb.xyz, qc.xyz);
  }
  first = v.radiance;
  second = v.transmittance;
}
)";
const char* const kDaylightDefines =
    "#define SKYBAKE_DAYLIGHT_LOOKUPS_ONLY 1\n#define SKYBAKE_NO_RADIANCE_TO_POINT 1\n"
    "#define SKYBAKE_NO_ECLIPSE_LOOKUPS 1\n#define SKYBAKE_BAKE_HAS_GROUND_VIEWS 1\n";

constexpr int kQueryRowWidth = 64;

struct Outputs {
  std::vector<Spectrum> first, second;
};

GLuint floatTexture(int width, int height, const std::vector<glm::vec4>& texels) {
  GLuint id = 0;
  glGenTextures(1, &id);
  glActiveTexture(GL_TEXTURE15);  // a unit neither the tables nor the queries use
  glBindTexture(GL_TEXTURE_2D, id);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT,
               texels.empty() ? nullptr : texels.data());
  return id;
}

class GlLookups {
 public:
  // `main`: kQueryMain, kEclipseQueryMain or kDaylightQueryMain.
  // `precision`: how the 4D tables are uploaded (runtime/tables/gpu_tables.h).
  // `defines`: before the library.
  explicit GlLookups(const Sky& sky, const char* main = kQueryMain,
                     GpuTablePrecision precision = GpuTablePrecision::Half, const std::string& defines = "")
      : resources_(sky, precision),
        program_(gl::kFullScreenVertexShader,
                 "#version 330 core\n" + defines + gl::skyGlslLibrary() + kQueryInputs + main) {}

  // One draw per kind of query: llvmpipe ends a shader's loops after 65535
  // passes counted over all the loops its lanes run together, and an
  // eclipse irradiance alone takes about half of that; lanes of one kind run
  // the same loops side by side.
  Outputs evaluate(const std::vector<Query>& queries) const {
    Outputs out;
    out.first.assign(queries.size(), Spectrum(0.0f));
    out.second.assign(queries.size(), Spectrum(0.0f));
    for (int kind = 0; kind <= static_cast<int>(Kind::EclipseRadianceToPoint); ++kind) {
      std::vector<Query> group;
      std::vector<size_t> at;
      for (size_t i = 0; i < queries.size(); ++i) {
        if (static_cast<int>(queries[i].kind) == kind) group.push_back(queries[i]), at.push_back(i);
      }
      if (group.empty()) continue;
      const Outputs part = evaluateOneDraw(group);
      for (size_t i = 0; i < at.size(); ++i) out.first[at[i]] = part.first[i], out.second[at[i]] = part.second[i];
    }
    return out;
  }

 private:
  Outputs evaluateOneDraw(const std::vector<Query>& queries) const {
    const int width = kQueryRowWidth;
    const int height = static_cast<int>((queries.size() + width - 1) / width);
    std::vector<glm::vec4> a(static_cast<size_t>(width) * height), b(a.size()), c(a.size()), m(a.size());
    for (size_t i = 0; i < queries.size(); ++i) {
      const Query& q = queries[i];
      a[i] = glm::vec4(q.a, q.shadow_length_m);
      b[i] = glm::vec4(q.b, 0.0f);
      c[i] = glm::vec4(q.sun, static_cast<float>(q.kind));
      m[i] = q.moon;
    }
    const GLuint p = program_.id();
    resources_.bind(p, 0);
    const GLuint inputs[4] = {floatTexture(width, height, a), floatTexture(width, height, b),
                              floatTexture(width, height, c), floatTexture(width, height, m)};
    const char* names[4] = {"query_a", "query_b", "query_c", "query_d"};
    for (int i = 0; i < 4; ++i) {
      glActiveTexture(GL_TEXTURE8 + i);
      glBindTexture(GL_TEXTURE_2D, inputs[i]);
      glUniform1i(glGetUniformLocation(p, names[i]), 8 + i);
    }
    const GLuint targets[2] = {floatTexture(width, height, {}), floatTexture(width, height, {})};
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, targets[0], 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, targets[1], 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
    glViewport(0, 0, width, height);
    gl::drawFullScreenTriangle();
    Outputs out;
    std::vector<glm::vec4> pixels(a.size());
    for (int i = 0; i < 2; ++i) {
      glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
      glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, pixels.data());
      (i == 0 ? out.first : out.second).assign(pixels.begin(), pixels.begin() + queries.size());
    }
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(2, targets);
    glDeleteTextures(4, inputs);
    return out;
  }

  gl::SkyGlResources resources_;
  gl::GlProgram program_;
};

Moon moonOf(const Query& q) { return {glm::dvec3(glm::vec3(q.moon)), q.moon.w}; }

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The test's own statement of what skybakeInSunDiskPastMoon decides: within
// the sun's angular radius of its centre, at least the moon's from the
// moon's centre seen from `camera`.
bool inSunDiskPastMoon(const glm::dvec3& camera, const glm::dvec3& dir, const glm::dvec3& sun, double sun_radius_rad,
                       const Moon& moon) {
  const glm::dvec3 to_moon = moon.centre_m - camera;
  return angleBetween(dir, sun) < sun_radius_rad &&
         angleBetween(dir, to_moon) >= std::asin(moon.radius_m / glm::length(to_moon));
}

Outputs evaluateOnCpu(const Sky& sky, const std::vector<Query>& queries) {
  Outputs out;
  for (const Query& q : queries) {
    const glm::dvec3 a(q.a), b(q.b), sun(q.sun);
    Spectrum first(0.0f), second(0.0f);
    switch (q.kind) {
      case Kind::SkyRadiance: {
        const RadianceAndTransmittance v = sky.skyRadiance(a, b, sun, q.shadow_length_m);
        first = v.radiance, second = v.transmittance;
        break;
      }
      case Kind::RadianceToPoint: {
        const RadianceAndTransmittance v = sky.radianceToPoint(a, b, sun, q.shadow_length_m);
        first = v.radiance, second = v.transmittance;
        break;
      }
      case Kind::Irradiance: {
        const SunAndSkyIrradiance e = sky.irradiance(a, b, sun);
        first = e.sun, second = e.sky;
        break;
      }
      case Kind::Transmittance:
        first = sky.transmittance(a, b);
        break;
      case Kind::Received: {
        const RadianceAndTransmittance v = sky.receivedRadiance(a, b, sun);
        first = v.radiance, second = v.transmittance;
        break;
      }
      case Kind::EclipseSkyRadiance: {
        const RadianceAndTransmittance v = sky.skyRadiance(a, b, {sun, moonOf(q)});
        first = v.radiance, second = v.transmittance;
        break;
      }
      case Kind::EclipseReceived: {
        const RadianceAndTransmittance v = sky.receivedRadiance(a, b, {sun, moonOf(q)});
        first = v.radiance, second = v.transmittance;
        break;
      }
      case Kind::EclipseRadianceToPoint: {
        const RadianceAndTransmittance v = sky.radianceToPoint(a, b, {sun, moonOf(q)});
        first = v.radiance, second = v.transmittance;
        break;
      }
      case Kind::EclipseIrradiance: {
        const SunAndSkyIrradiance e = sky.irradiance(a, b, {sun, moonOf(q)});
        first = e.sun, second = e.sky;
        break;
      }
      case Kind::EclipseSkylightAndSun:
      case Kind::EclipseSun: {
        const Moon moon = moonOf(q);
        if (q.kind == Kind::EclipseSkylightAndSun) first = sky.eclipseSkylight(a, {sun, moon});
        const double alpha = sky.atmosphere().sun_angular_radius_rad;
        second = Spectrum(static_cast<float>(moon.visibleSunFraction(a, sun, alpha)),
                          inSunDiskPastMoon(a, glm::normalize(b), sun, alpha, moon) ? 1.0f : 0.0f, 0.0f, 0.0f);
        break;
      }
      case Kind::Luminance: {
        const RadianceAndTransmittance v = sky.skyRadiance(a, b, sun, q.shadow_length_m);
        first = Spectrum(static_cast<float>(sky.luminance(v.radiance)),
                         sky.channels().kind == ChannelKind::CieXyz ? 1.0f : 0.0f, 0.0f, 0.0f);
        break;
      }
    }
    out.first.push_back(first);
    out.second.push_back(second);
  }
  return out;
}

// See the tolerance note at the top.
constexpr double kValueFloor = 1e-5;
constexpr double kMaxRmsRelative = 0.005;
constexpr double kMaxRelative = 0.02;

struct Difference {
  double rms = 0.0, largest = 0.0;
  size_t count = 0, non_finite = 0, worst = 0;
};

Difference compare(const std::vector<Spectrum>& cpu, const std::vector<Spectrum>& gpu, int channels,
                   double value_floor = kValueFloor) {
  Difference d;
  double sum = 0.0;
  for (size_t i = 0; i < cpu.size(); ++i) {
    for (int c = 0; c < channels; ++c) {
      if (!std::isfinite(gpu[i][c])) ++d.non_finite;
      if (!(cpu[i][c] > value_floor)) continue;
      const double relative = std::abs(static_cast<double>(gpu[i][c]) - cpu[i][c]) / cpu[i][c];
      sum += relative * relative;
      if (relative > d.largest) d.largest = relative, d.worst = i;
      ++d.count;
    }
  }
  d.rms = d.count > 0 ? std::sqrt(sum / d.count) : 0.0;
  return d;
}

void expectParity(const Sky& sky, const GlLookups& gl, const std::vector<Query>& queries, const std::string& what,
                  double value_floor = kValueFloor) {
  const Outputs cpu = evaluateOnCpu(sky, queries);
  const Outputs gpu = gl.evaluate(queries);
  for (int output = 0; output < 2; ++output) {
    const Difference d = compare(output == 0 ? cpu.first : cpu.second, output == 0 ? gpu.first : gpu.second,
                                 sky.channelCount(), value_floor);
    const Spectrum& c = (output == 0 ? cpu.first : cpu.second)[d.worst];
    const Spectrum& g = (output == 0 ? gpu.first : gpu.second)[d.worst];
    std::printf("%s, output %d: rms %.4f %% max %.4f %% over %zu values (worst query %zu: cpu %g %g %g, gl %g %g %g)\n",
                what.c_str(), output, 100.0 * d.rms, 100.0 * d.largest, d.count, d.worst, c[0], c[1], c[2], g[0], g[1],
                g[2]);
    EXPECT_EQ(d.non_finite, 0u) << what;
    EXPECT_LE(d.rms, kMaxRmsRelative) << what << " output " << output;
    EXPECT_LE(d.largest, kMaxRelative) << what << " output " << output;
  }
}

glm::vec3 sunAt(double zenith_deg, double azimuth_deg = 0.0) {
  const double z = radiansFromDegrees(zenith_deg), a = radiansFromDegrees(azimuth_deg);
  return glm::vec3(std::sin(z) * std::cos(a), std::sin(z) * std::sin(a), std::cos(z));
}

// Unit directions uniform over the sphere, fixed seed.
std::vector<glm::vec3> directions(size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<glm::vec3> out;
  for (size_t i = 0; i < count; ++i) {
    const float z = 2.0f * uniform(rng) - 1.0f, phi = 6.2831853f * uniform(rng);
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    out.emplace_back(s * std::cos(phi), s * std::sin(phi), z);
  }
  return out;
}

std::string bakePath(const char* name) { return std::string(SKYBAKE_GL_TEST_BAKE_DIR) + "/" + name; }

class GlParity : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = new gl::HeadlessGlContext(); }
  static void TearDownTestSuite() {
    delete eclipse_lookups_;
    eclipse_lookups_ = nullptr;
    delete eclipse_sky_;
    eclipse_sky_ = nullptr;
    delete context_;
    context_ = nullptr;
  }
  // gl_earth.exr and its eclipse program, compiled once for the eclipse tests.
  static const Sky& eclipseSky() {
    if (eclipse_sky_ == nullptr) eclipse_sky_ = new Sky(Sky::load(bakePath("gl_earth.exr")));
    return *eclipse_sky_;
  }
  static const GlLookups& eclipseLookups() {
    if (eclipse_lookups_ == nullptr) eclipse_lookups_ = new GlLookups(eclipseSky(), kEclipseQueryMain);
    return *eclipse_lookups_;
  }
  static gl::HeadlessGlContext* context_;
  static Sky* eclipse_sky_;
  static GlLookups* eclipse_lookups_;
};
gl::HeadlessGlContext* GlParity::context_ = nullptr;
Sky* GlParity::eclipse_sky_ = nullptr;
GlLookups* GlParity::eclipse_lookups_ = nullptr;

// Sky radiance from the ground, 30 km and orbit, day to deep twilight,
// with and without light shafts.
TEST_F(GlParity, SkyRadiance) {
  const Sky sky = Sky::load(bakePath("gl_earth.exr"));
  const GlLookups gl(sky);
  const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
  for (double sun_zenith : {30.0, 85.0, 95.0}) {
    for (float altitude : {0.0f, 30000.0f, 400000.0f}) {
      std::vector<Query> queries;
      for (const glm::vec3& d : directions(512, 7)) {
        queries.push_back({Kind::SkyRadiance, glm::vec3(0.0f, 0.0f, bottom + altitude), d, sunAt(sun_zenith, 20.0)});
      }
      expectParity(
          sky, gl, queries,
          "sky radiance, sun " + std::to_string(sun_zenith) + " deg, altitude " + std::to_string(altitude) + " m");
    }
  }
}

// A program of daylight lookups (SKYBAKE_DAYLIGHT_LOOKUPS_ONLY and the
// defines leaving out radiance to points and eclipses: `skybake render
// --backend gl`'s and `skybake view`'s by day) gives what the whole
// library gives, for cameras in the atmosphere under every sun
// daylightLookupsSuffice admits, down to the last such degree.
// The two programs do the same arithmetic on the same texels: they differ
// only where a compiler orders or fuses it differently, a few float
// roundings (1e-6 relative allowed, 8 roundings of 2^-24 each); the CPU as
// above.
TEST_F(GlParity, DaylightProgramGivesTheWholeLibrarysDaylight) {
  const Sky sky = Sky::load(bakePath("gl_earth.exr"));
  const GlLookups whole(sky);
  const GlLookups daylight(sky, kDaylightQueryMain, GpuTablePrecision::Half,
                           std::string(kDaylightDefines) + "#define SKYBAKE_BAKE_HAS_GROUND_VIEWS 1\n");
  const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
  constexpr double kLastDaylightZenithDeg = 88.9;  // cos 88.9 deg = 0.0192, the integral's top cosine 0.0175
  for (double sun_zenith : {20.0, 70.0, kLastDaylightZenithDeg}) {
    for (float altitude : {0.0f, 30000.0f, 59000.0f}) {  // the top at 60 km
      const glm::vec3 camera(0.0f, 0.0f, bottom + altitude);
      ASSERT_TRUE(gl::daylightLookupsSuffice(sky, camera, sunAt(sun_zenith, 20.0))) << sun_zenith;
      std::vector<Query> queries;
      for (const glm::vec3& d : directions(512, 13)) {
        for (Kind kind : {Kind::SkyRadiance, Kind::Received}) {
          queries.push_back({kind, camera, d, sunAt(sun_zenith, 20.0)});
        }
      }
      const std::string what =
          "daylight program, sun " + std::to_string(sun_zenith) + " deg, altitude " + std::to_string(altitude) + " m";
      expectParity(sky, daylight, queries, what);
      const Outputs a = whole.evaluate(queries);
      const Outputs b = daylight.evaluate(queries);
      for (int output = 0; output < 2; ++output) {
        const Difference d =
            compare(output == 0 ? a.first : a.second, output == 0 ? b.first : b.second, sky.channelCount());
        EXPECT_LE(d.largest, 1e-6) << what << " against the whole library, output " << output;
        EXPECT_GT(d.count, 0u) << what;
      }
    }
  }
}

// What daylightLookupsSuffice refuses: a sun within the integral's degree
// of the horizon or below it, a camera above the atmosphere, and a scene
// narrowed to day suns whose sun is below the horizon (its tables then
// blend across the sun geometrically, though no integral weighs in; this
// scene's bake, without ground views, is refused by day as well).
TEST_F(GlParity, DaylightLookupsSufficeOnlyByDayInTheAtmosphere) {
  const Sky earth = Sky::load(bakePath("gl_earth.exr"));
  const Sky scene = Sky::load(bakePath("gl_scene.exr"));
  const glm::dvec3 ground(0.0, 0.0, earth.atmosphere().bottom_radius_m);
  const glm::dvec3 above(0.0, 0.0, earth.atmosphere().top_radius_m + 1000.0);
  EXPECT_TRUE(gl::daylightLookupsSuffice(earth, ground, sunAt(88.9)));
  EXPECT_FALSE(gl::daylightLookupsSuffice(earth, ground, sunAt(89.5)));
  EXPECT_FALSE(gl::daylightLookupsSuffice(earth, ground, sunAt(120.0)));
  EXPECT_FALSE(gl::daylightLookupsSuffice(earth, above, sunAt(20.0)));
  EXPECT_FALSE(gl::daylightLookupsSuffice(scene, ground, sunAt(100.0)));
  EXPECT_FALSE(gl::daylightLookupsSuffice(scene, ground, sunAt(20.0)));
  EXPECT_EQ(scene.integratedSingleScatteringWeightAt(std::cos(radiansFromDegrees(100.0))), 0.0);
}

// The same from tables uploaded as RGBA32F (gl_earth.toml is a float bake:
// the half upload above rounds each texel by up to 2^-11, this one not at
// all), so both upload paths are held to the CPU.
TEST_F(GlParity, SkyRadianceFromAFloatUpload) {
  const Sky sky = Sky::load(bakePath("gl_earth.exr"));
  const GlLookups gl(sky, kQueryMain, GpuTablePrecision::Float);
  const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
  for (double sun_zenith : {30.0, 95.0}) {
    std::vector<Query> queries;
    for (const glm::vec3& d : directions(512, 11)) {
      queries.push_back({Kind::SkyRadiance, glm::vec3(0.0f, 0.0f, bottom + 1000.0f), d, sunAt(sun_zenith, 20.0)});
    }
    expectParity(sky, gl, queries, "sky radiance, float upload, sun " + std::to_string(sun_zenith) + " deg");
  }
}

// Below the baked sun angles (gl_earth.toml bakes down to 102 deg): the night
// continuation of the tables and single scattering integrated for the sun
// where it is, up to the dark angle (121.4 deg) and beyond, where both give
// the night floor. The sky there is 1e-8 to 1e-14 of the day's, far below
// kValueFloor; float keeps its relative precision down to 1e-38, so the same
// relative tolerances hold for every value above 1e-30.
constexpr double kNightValueFloor = 1e-30;

TEST_F(GlParity, SunBelowTheBakedAngles) {
  const Sky sky = Sky::load(bakePath("gl_earth.exr"));
  const GlLookups gl(sky);
  const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
  for (double sun_zenith : {102.5, 105.0, 110.0, 118.0, 130.0, 180.0}) {
    for (float altitude : {0.0f, 30000.0f, 400000.0f}) {
      std::vector<Query> queries;
      const glm::vec3 camera(0.0f, 0.0f, bottom + altitude);
      for (const glm::vec3& d : directions(256, 11)) {
        queries.push_back({Kind::SkyRadiance, camera, d, sunAt(sun_zenith, 20.0)});
        queries.push_back(
            {Kind::Irradiance, camera, glm::normalize(d + glm::vec3(0.0f, 0.0f, 1.5f)), sunAt(sun_zenith, 20.0)});
      }
      const std::string what = "below the baked suns, sun " + std::to_string(sun_zenith) + " deg, altitude " +
                               std::to_string(altitude) + " m";
      expectParity(sky, gl, queries, what, kNightValueFloor);
      // Beyond the dark angle, from inside the atmosphere, the GL sky is the
      // night floor too (the parity above compares only values above it).
      if (sun_zenith >= 130.0 && altitude < sky.atmosphere().top_radius_m - sky.atmosphere().bottom_radius_m) {
        const Outputs out = gl.evaluate(queries);
        for (size_t i = 0; i < queries.size(); ++i) {
          for (int c = 0; c < sky.channelCount(); ++c) {
            EXPECT_EQ(out.first[i][c], 0.0f) << what << ", query " << i;
            if (queries[i].kind == Kind::Irradiance) {
              EXPECT_EQ(out.second[i][c], 0.0f) << what << ", query " << i;
            }
          }
        }
      }
    }
  }
}

// Aerial perspective toward points on the ground and in the air, short
// (integrated directly) and long (difference of lookups), day and twilight,
// with and without a shadow; in the whole and in the narrowed bake.
TEST_F(GlParity, RadianceToPoint) {
  for (const char* bake : {"gl_earth.exr", "gl_scene.exr"}) {
    const Sky sky = Sky::load(bakePath(bake));
    const GlLookups gl(sky);
    const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
    for (double sun_zenith : {30.0, 85.0, 95.0}) {
      std::vector<Query> queries;
      const glm::vec3 camera(0.0f, 0.0f, bottom + 1000.0f);
      int i = 0;
      for (const glm::vec3& d : directions(768, 11)) {
        // 2 km to 60 km: both sides of the direct / difference blend.
        const float distance_m = 2000.0f * std::pow(30.0f, static_cast<float>(i % 16) / 15.0f);
        // Positions rounded to float, so the CPU sees the query the GPU does.
        const glm::vec3 point = camera + d * distance_m;
        queries.push_back({Kind::RadianceToPoint, camera, point, sunAt(sun_zenith, 40.0), i % 5 == 0 ? 500.0f : 0.0f});
        ++i;
      }
      expectParity(sky, gl, queries, std::string(bake) + ": radiance to a point, sun " + std::to_string(sun_zenith));
    }
  }
}

// Under a sun just above the camera's horizon, points hundreds of km away
// from the sun and long light shafts end where the sun is below the
// horizon: the single-scattering tables are not uploaded there
// (runtime/tables/gpu_tables.h), and the lookups integrate single
// scattering along the ray instead, the C++ and the GLSL alike.
TEST_F(GlParity, FarEndsPastTheTerminator) {
  const Sky sky = Sky::load(bakePath("gl_earth.exr"));
  const GlLookups gl(sky);
  const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
  const glm::vec3 camera(0.0f, 0.0f, bottom + 1000.0f);
  for (double sun_zenith : {88.0, 89.5}) {
    std::vector<Query> queries;
    for (int i = 0; i < 256; ++i) {
      // Away from the sun (azimuth 120 to 240 deg), 80 to 92 deg from the
      // zenith: 300 km away the sun is 2.7 deg lower.
      const double azimuth = radiansFromDegrees(120.0 + 120.0 * (i % 16) / 15.0);
      const double zenith = radiansFromDegrees(80.0 + 12.0 * (i / 16) / 15.0);
      const glm::vec3 d(static_cast<float>(std::sin(zenith) * std::cos(azimuth)),
                        static_cast<float>(std::sin(zenith) * std::sin(azimuth)), static_cast<float>(std::cos(zenith)));
      const float reach_m = 50000.0f + 25000.0f * static_cast<float>(i % 23);  // 50 to 600 km
      if (i % 2 == 0) {
        queries.push_back({Kind::RadianceToPoint, camera, camera + d * reach_m, sunAt(sun_zenith)});
      } else {
        queries.push_back({Kind::SkyRadiance, camera, d, sunAt(sun_zenith), reach_m});
      }
    }
    expectParity(sky, gl, queries, "far ends past the terminator, sun " + std::to_string(sun_zenith));
  }
}

// What `skybake info` states an upload takes is what skyGpuTextures
// uploads, and the single-scattering tables start at the last sun texel at
// or below the horizon.
TEST(GlUpload, BytesAreTheTexturesAndSingleScatteringStartsAtTheHorizon) {
  for (const char* bake : {"gl_earth.exr", "gl_scene.exr"}) {
    const Sky sky = Sky::load(bakePath(bake));
    for (GpuTablePrecision precision : {GpuTablePrecision::Half, GpuTablePrecision::Float}) {
      uint64_t bytes = 0;
      for (const gl::GpuTexture& t : gl::skyGpuTextures(sky, precision)) {
        EXPECT_EQ(t.bytes().size(), static_cast<size_t>(t.width) * t.height * t.depth * gl::gpuTexelBytes(t.format))
            << bake << " " << t.sampler;
        bytes += t.bytes().size();
      }
      EXPECT_EQ(bytes, gpuUploadBytes(sky.contents(), precision).total()) << bake;
    }
    const AtmosphereDomain& domain = sky.contents().domain;
    const ScatteringSizes sizes = ScatteringSizes::fromTextureSizes(sky.contents().sizes);
    const int first = singleScatteringFirstSunTexel(domain, sizes);
    if (first > 0) EXPECT_LE(muSFromScatteringTexel(domain, sizes, first), 0.0) << bake;
    EXPECT_GT(muSFromScatteringTexel(domain, sizes, first + 1), 0.0) << bake;
    const std::vector<gl::GpuTexture> textures = gl::skyGpuTextures(sky, GpuTablePrecision::Half);
    EXPECT_EQ(textures[1].width, sizes.nu * (sizes.mu_s - first)) << bake;  // skybake_single_rayleigh
    EXPECT_EQ(textures[3].width, sizes.nu * sizes.mu_s) << bake;            // skybake_multiple_scattering
    if (std::string(bake) == "gl_earth.exr") EXPECT_GT(first, 0) << "its suns reach below the horizon";
  }
}

// Light shafts, the lit ground, the narrowed bake's integrated ground rays.
TEST_F(GlParity, ShadowsGroundAndNarrowedScene) {
  for (const char* bake : {"gl_earth.exr", "gl_scene.exr"}) {
    const Sky sky = Sky::load(bakePath(bake));
    const GlLookups gl(sky);
    const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
    for (double sun_zenith : {40.0, 92.0}) {
      std::vector<Query> queries;
      int i = 0;
      for (const glm::vec3& d : directions(512, 5)) {
        const glm::vec3 camera(0.0f, 0.0f, bottom + 2000.0f);
        const Kind kind = i % 2 == 0 ? Kind::SkyRadiance : Kind::Received;
        queries.push_back({kind, camera, d, sunAt(sun_zenith), kind == Kind::SkyRadiance ? 3000.0f * (i % 4) : 0.0f});
        ++i;
      }
      expectParity(sky, gl, queries, std::string(bake) + ": shafts and ground, sun " + std::to_string(sun_zenith));
    }
  }
}

// Sun and sky irradiance on tilted surfaces at several altitudes, and
// transmittance along segments (some through the ground, some from space).
TEST_F(GlParity, IrradianceAndTransmittance) {
  const Sky sky = Sky::load(bakePath("gl_earth.exr"));
  const GlLookups gl(sky);
  const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
  const float top = static_cast<float>(sky.atmosphere().top_radius_m);
  std::vector<Query> irradiance, transmittance;
  int i = 0;
  for (const glm::vec3& d : directions(512, 3)) {
    // Every fourth point in the last 4 km below the top, where the sky
    // irradiance follows the air above (TableSampler::irradiance).
    const float radius =
        i % 4 == 3 ? top - 137.0f * static_cast<float>(i % 29) : bottom + 500.0f * static_cast<float>(i % 9);
    const glm::vec3 point(0.0f, 0.0f, radius);
    const glm::vec3 normal = glm::normalize(d + glm::vec3(0.0f, 0.0f, 1.0f));
    irradiance.push_back({Kind::Irradiance, point, normal, sunAt(5.0 + 0.2 * (i % 470))});
    const glm::vec3 a(0.0f, 0.0f, bottom + (i % 3 == 0 ? 500000.0f : 100.0f * (i % 7)));
    transmittance.push_back({Kind::Transmittance, a, a + d * (1000.0f + 200.0f * (i % 50) * (i % 50)), sunAt(30.0)});
    ++i;
  }
  expectParity(sky, gl, irradiance, "irradiance");
  expectParity(sky, gl, transmittance, "transmittance");
}

// Solar eclipses: the sky radiance, the received radiance of the ground,
// the irradiance, the skylight share F and the sun's visible fraction under
// a moon in front of a sun 40 deg high: total (at the umbra's centre and
// 40 km off its axis), annular, partial and just outside the umbra, from
// the ground and from 10 km, views toward, across and away from the sun,
// near the horizon and at the ground.
//
// Tolerance: that of the other lookups (kMaxRmsRelative, kMaxRelative)
// over values above kEclipseValueFloor. The eclipse lookups add to the plain
// ones ratios of float sums: single scattering with and without the moon at
// the same 64 or more Gauss nodes, F's 4096 kernel points, the irradiance
// share's 48 directions; each sum of positive terms keeps float's 1e-6
// relative error per term. The moon's visible fraction is computed in float
// from a moon centre 384 400 km away (32 m resolution, 1e-7 rad in
// direction) against the sun's 4.7e-3 rad: 2e-5 of the disk. In totality
// the sky is 1e-3 of the day's (about 1e-6 to 1e-5 W m^-2 sr^-1 nm^-1 in
// this small bake): float keeps its relative precision there, so values
// down to 1e-9 are compared with the same relative tolerances.
constexpr double kEclipseValueFloor = 1e-9;

// The eclipse tests' sun (zenith angle, deg) and moons, each separation_deg
// above the sun seen from the camera: total at the umbra's centre and 40 km
// off its axis, annular, partial, and just outside the umbra.
constexpr double kEclipseSunZenith_deg = 50.0;
struct EclipseMoonCase {
  double separation_deg, angular_radius_deg;
};
constexpr EclipseMoonCase kEclipseMoons[] = {{0.0, 0.28}, {0.006, 0.28}, {0.0, 0.25}, {0.25, 0.28}, {0.03, 0.28}};

// The moon of m seen from camera, as the GLSL takes it (centre in metres
// from the planet's centre, radius in metres).
glm::vec4 eclipseMoonSeenFrom(const glm::vec3& camera, const EclipseMoonCase& m) {
  const glm::dvec3 moon_dir(sunAt(kEclipseSunZenith_deg - m.separation_deg));
  const Moon moon = Moon::seenFrom(glm::dvec3(camera), moon_dir, radiansFromDegrees(m.angular_radius_deg));
  return glm::vec4(glm::vec3(moon.centre_m), static_cast<float>(moon.radius_m));
}

// Calls f(camera, moon) for cameras on the ground and at 10 km above the
// origin's vertical and every moon of kEclipseMoons seen from there.
template <class F>
void forEachEclipseCameraAndMoon(double bottom_radius_m, F&& f) {
  for (double altitude_m : {0.0, 10000.0}) {
    const glm::vec3 camera(0.0f, 0.0f, static_cast<float>(bottom_radius_m + altitude_m));
    for (const EclipseMoonCase& m : kEclipseMoons) f(camera, eclipseMoonSeenFrom(camera, m));
  }
}

TEST_F(GlParity, EclipseSkyRadiance) {
  const Sky& sky = eclipseSky();
  const GlLookups& gl = eclipseLookups();
  const double bottom = sky.atmosphere().bottom_radius_m;
  const glm::vec3 sun = sunAt(kEclipseSunZenith_deg);
  // Views: zenith angle, azimuth from the sun's (deg).
  const double views[][2] = {{0.0, 0.0},  {45.0, 0.0},  {45.0, 90.0},  {45.0, 180.0},
                             {85.0, 0.0}, {88.0, 90.0}, {89.5, 180.0}, {120.0, 30.0}};
  std::vector<Query> queries;
  forEachEclipseCameraAndMoon(bottom, [&](const glm::vec3& camera, const glm::vec4& moon_f) {
    for (const auto& v : views) {
      const glm::vec3 dir = sunAt(v[0], v[1]);
      queries.push_back({Kind::EclipseSkyRadiance, camera, dir, sun, 0.0f, moon_f});
      if (v[0] > 90.0) queries.push_back({Kind::EclipseReceived, camera, dir, sun, 0.0f, moon_f});
    }
    queries.push_back({Kind::EclipseIrradiance, camera, glm::vec3(0.0f, 0.0f, 1.0f), sun, 0.0f, moon_f});
    queries.push_back({Kind::EclipseSkylightAndSun, camera, sun, sun, 0.0f, moon_f});
    // F and the visible fraction 30 km up the sun's direction and 60 km
    // across it: other parts of the shadow.
    queries.push_back({Kind::EclipseSkylightAndSun, camera + sun * 30000.0f, sun, sun, 0.0f, moon_f});
    queries.push_back({Kind::EclipseSkylightAndSun, camera + glm::vec3(60000.0f, 0.0f, 0.0f), sun, sun, 0.0f, moon_f});
  });
  expectParity(sky, gl, queries, "eclipse", kEclipseValueFloor);
}

// Radiance to points 5 to 120 km away under the same moons (total at the
// umbra's centre and 40 km off its axis, the camera inside the umbra;
// annular; partial; just outside the umbra, the camera outside it), from
// the ground and from 10 km, toward, across and away from the sun, near the
// horizon and down toward the ground (points below it left out). The
// segment's single scattering with and without the moon are float sums at
// the same 64 Gauss nodes as the sky's (the tolerance note above), and what
// the plain lookup scattered more than once is the plain value less the
// second of them: the same tolerances, over the same value floor.
TEST_F(GlParity, EclipseRadianceToPoint) {
  const Sky& sky = eclipseSky();
  const GlLookups& gl = eclipseLookups();
  const double bottom = sky.atmosphere().bottom_radius_m;
  const glm::vec3 sun = sunAt(kEclipseSunZenith_deg);
  // Views: zenith angle, azimuth from the sun's (deg).
  const double views[][2] = {{80.0, 0.0}, {60.0, 90.0}, {85.0, 180.0}, {89.0, 90.0}, {100.0, 30.0}};
  std::vector<Query> queries;
  forEachEclipseCameraAndMoon(bottom, [&](const glm::vec3& camera, const glm::vec4& moon_f) {
    for (const auto& v : views) {
      for (float distance_m : {5000.0f, 20000.0f, 60000.0f, 120000.0f}) {
        // Positions rounded to float, so the CPU sees the query the GPU does.
        const glm::vec3 point = camera + sunAt(v[0], v[1]) * distance_m;
        if (glm::length(glm::dvec3(point)) < bottom) continue;
        queries.push_back({Kind::EclipseRadianceToPoint, camera, point, sun, 0.0f, moon_f});
      }
    }
  });
  expectParity(sky, gl, queries, "eclipse radiance to a point", kEclipseValueFloor);
}

// A moon far from the sun hides it from nowhere in the atmosphere: the
// eclipse lookups give the plain ones' values. The same float operations,
// but compiled in another program, whose compiler may fuse a multiply and
// an add differently: a few units in the last place, so 1e-5 relative.
constexpr double kSameOperationsTolerance = 1e-5;

TEST_F(GlParity, EclipseWithTheMoonAwayIsPlain) {
  const Sky& sky = eclipseSky();
  const GlLookups& gl = eclipseLookups();
  const glm::vec3 camera(0.0f, 0.0f, static_cast<float>(sky.atmosphere().bottom_radius_m + 500.0));
  const glm::vec3 sun = sunAt(50.0);
  const Moon moon = Moon::seenFrom(glm::dvec3(camera), glm::dvec3(sunAt(45.0)), radiansFromDegrees(0.28));
  const glm::vec4 moon_f(glm::vec3(moon.centre_m), static_cast<float>(moon.radius_m));
  std::vector<Query> plain, eclipsed;
  for (const glm::vec3& d : directions(32, 13)) {
    plain.push_back({Kind::Received, camera, d, sun});
    eclipsed.push_back({Kind::EclipseReceived, camera, d, sun, 0.0f, moon_f});
    plain.push_back({Kind::RadianceToPoint, camera, camera + d * 30000.0f, sun});
    eclipsed.push_back({Kind::EclipseRadianceToPoint, camera, camera + d * 30000.0f, sun, 0.0f, moon_f});
  }
  plain.push_back({Kind::Irradiance, camera, glm::vec3(0.0f, 0.0f, 1.0f), sun});
  eclipsed.push_back({Kind::EclipseIrradiance, camera, glm::vec3(0.0f, 0.0f, 1.0f), sun, 0.0f, moon_f});
  const Outputs a = GlLookups(sky).evaluate(plain), b = gl.evaluate(eclipsed);
  for (size_t i = 0; i < plain.size(); ++i) {
    for (int c = 0; c < 4; ++c) {
      EXPECT_NEAR(a.first[i][c], b.first[i][c], kSameOperationsTolerance * a.first[i][c]) << "query " << i;
      EXPECT_NEAR(a.second[i][c], b.second[i][c], kSameOperationsTolerance * a.second[i][c]) << "query " << i;
    }
  }
}

// The sun disk past the moon: view directions across the sun disk with a
// partial eclipse's moon over part of it, classified as the test states it
// in double (directions within 1e-5 rad of either limb, closer than float
// resolves the disk's edge through the chord test, are skipped).
TEST_F(GlParity, EclipseSunDiskPastMoon) {
  const Sky& sky = eclipseSky();
  const GlLookups& gl = eclipseLookups();
  const double alpha = sky.atmosphere().sun_angular_radius_rad;
  const glm::vec3 camera(0.0f, 0.0f, static_cast<float>(sky.atmosphere().bottom_radius_m));
  const glm::vec3 sun = sunAt(50.0);
  const Moon moon = Moon::seenFrom(glm::dvec3(camera), glm::dvec3(sunAt(49.8)), radiansFromDegrees(0.28));
  const glm::vec4 moon_f(glm::vec3(moon.centre_m), static_cast<float>(moon.radius_m));
  const glm::dvec3 to_moon = glm::dvec3(glm::vec3(moon_f)) - glm::dvec3(camera);
  const double moon_radius = std::asin(moon_f.w / glm::length(to_moon));
  std::vector<Query> queries;
  int inside = 0;
  for (int i = 0; i < 24; ++i) {
    for (int j = 0; j < 24; ++j) {
      const glm::vec3 dir = sunAt(50.0 + 0.6 * (i / 23.0 - 0.5), 0.8 * (j / 23.0 - 0.5));
      const double to_sun_edge = std::abs(angleBetween(glm::dvec3(dir), glm::dvec3(sun)) - alpha);
      const double to_moon_edge = std::abs(angleBetween(glm::dvec3(dir), to_moon) - moon_radius);
      if (to_sun_edge < 1e-5 || to_moon_edge < 1e-5) continue;
      queries.push_back({Kind::EclipseSun, camera, dir, sun, 0.0f, moon_f});
    }
  }
  const Outputs cpu = evaluateOnCpu(sky, queries), gpu = gl.evaluate(queries);
  for (size_t i = 0; i < queries.size(); ++i) {
    EXPECT_EQ(gpu.second[i][1], cpu.second[i][1]) << "query " << i;
    inside += cpu.second[i][1] > 0.5f ? 1 : 0;
  }
  // Both kinds of direction are there: the test sees the moon's limb.
  EXPECT_GT(inside, 10);
  EXPECT_LT(inside, static_cast<int>(queries.size()) - 10);
}

// Hostile moons, as the C++ eclipse tests take them: a camera inside the
// moon, a moon bigger than its distance, a small near one, a centre that is
// not a number: every GL output finite and not negative (radiance to points
// 20 km away among them).
TEST_F(GlParity, EclipseHostileMoonsAreFinite) {
  const Sky& sky = eclipseSky();
  const GlLookups& gl = eclipseLookups();
  const glm::vec3 camera(0.0f, 0.0f, static_cast<float>(sky.atmosphere().bottom_radius_m + 1000.0));
  const glm::vec3 sun = sunAt(50.0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const glm::vec4 moons[] = {glm::vec4(camera, 5000.0f), glm::vec4(camera + sun * 1e9f, 1e9f),
                             glm::vec4(camera + sun * 20e3f, 3e3f), glm::vec4(nan, 0.0f, 0.0f, 1.7e6f)};
  std::vector<Query> queries;
  for (const glm::vec4& moon : moons) {
    for (const glm::vec3& d : {sunAt(0.0), sunAt(50.0), sunAt(89.0, 90.0), sunAt(120.0)}) {
      queries.push_back({Kind::EclipseReceived, camera, d, sun, 0.0f, moon});
      queries.push_back({Kind::EclipseSun, camera, d, sun, 0.0f, moon});
      queries.push_back({Kind::EclipseRadianceToPoint, camera, camera + d * 20000.0f, sun, 0.0f, moon});
    }
    queries.push_back({Kind::EclipseIrradiance, camera, glm::vec3(0.0f, 0.0f, 1.0f), sun, 0.0f, moon});
    queries.push_back({Kind::EclipseSkylightAndSun, camera, sun, sun, 0.0f, moon});
  }
  const Outputs out = gl.evaluate(queries);
  for (size_t i = 0; i < queries.size(); ++i) {
    for (int c = 0; c < 4; ++c) {
      EXPECT_TRUE(std::isfinite(out.first[i][c]) && out.first[i][c] >= 0.0f)
          << "query " << i << ": " << out.first[i][c];
      EXPECT_TRUE(std::isfinite(out.second[i][c]) && out.second[i][c] >= 0.0f)
          << "query " << i << ": " << out.second[i][c];
    }
  }
}

// Hostile geometry: cameras below the ground, at the centre, far in space,
// rays grazing the ground and the top, suns below every baked angle: every
// GL output finite.
TEST_F(GlParity, HostileGeometryIsFinite) {
  const Sky sky = Sky::load(bakePath("gl_scene.exr"));
  const GlLookups gl(sky);
  const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
  const float top = static_cast<float>(sky.atmosphere().top_radius_m);
  const glm::vec3 cameras[] = {glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, bottom - 5000.0f), glm::vec3(0.0f, 0.0f, bottom),
                               glm::vec3(0.0f, 0.0f, top), glm::vec3(0.0f, 0.0f, 1e9f)};
  const glm::vec3 grazing[] = {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f),
                               glm::normalize(glm::vec3(1.0f, 0.0f, -1e-4f))};
  std::vector<Query> queries;
  for (const glm::vec3& camera : cameras) {
    for (const glm::vec3& d : grazing) {
      for (double sun_zenith : {0.0, 90.0, 120.0, 180.0}) {
        for (int kind = 0; kind < 5; ++kind) {
          queries.push_back({static_cast<Kind>(kind), camera, kind == 1 || kind == 3 ? camera + d * 1e5f : d,
                             sunAt(sun_zenith), kind == 0 ? 1e7f : 0.0f});
        }
      }
    }
  }
  const Outputs out = gl.evaluate(queries);
  for (size_t i = 0; i < queries.size(); ++i) {
    for (int c = 0; c < 4; ++c) {
      EXPECT_TRUE(std::isfinite(out.first[i][c]) && std::isfinite(out.second[i][c])) << "query " << i;
    }
  }
}

// No EGL display at all: a BadInput error that says so, not a crash.
// skybakeLuminance against Sky::luminance, for a wavelength bake (weights
// through the CIE 1931 ybar) and a colour bake (683 Y): the sky radiance's
// luminance within the radiance's tolerances (a weighted sum of lanes each
// within them), and the channel kind exactly. Luminance above 1e-2 cd m^-2
// (683 times kValueFloor's radiance) is compared.
TEST_F(GlParity, LuminanceOfWavelengthAndColourBakes) {
  for (const char* bake : {"gl_earth.exr", "gl_colour.exr"}) {
    const Sky sky = Sky::load(bakePath(bake));
    const GlLookups gl(sky);
    const float bottom = static_cast<float>(sky.atmosphere().bottom_radius_m);
    std::vector<Query> queries;
    for (double sun_zenith : {30.0, 85.0, 95.0}) {
      for (const glm::vec3& d : directions(256, 11)) {
        queries.push_back({Kind::Luminance, glm::vec3(0.0f, 0.0f, bottom + 100.0f), d, sunAt(sun_zenith, 20.0)});
      }
    }
    const Outputs cpu = evaluateOnCpu(sky, queries);
    const Outputs gpu = gl.evaluate(queries);
    const Difference d = compare(cpu.first, gpu.first, 1, 683.0 * kValueFloor);
    std::printf("%s luminance: rms %.4f %% max %.4f %% over %zu values\n", bake, 100.0 * d.rms, 100.0 * d.largest,
                d.count);
    EXPECT_GT(d.count, queries.size() / 3) << bake;
    EXPECT_EQ(d.non_finite, 0u) << bake;
    EXPECT_LE(d.rms, kMaxRmsRelative) << bake;
    EXPECT_LE(d.largest, kMaxRelative) << bake;
    for (size_t i = 0; i < queries.size(); ++i) ASSERT_EQ(gpu.first[i][1], cpu.first[i][1]) << bake;
  }
}

TEST(GlContext, NoDisplayIsBadInput) {
  const char* saved = std::getenv("EGL_PLATFORM");
  setenv("EGL_PLATFORM", "nonexistent_platform", 1);
  setenv("EGL_DRIVERS_PATH", "/nonexistent", 1);
  setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent.json", 1);
  try {
    gl::HeadlessGlContext context;
    // With no EGL vendor library libglvnd has no driver to offer, so this
    // is a context from somewhere the test did not expect.
    ADD_FAILURE() << "a context was made without any EGL vendor: " << context.description();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("no headless OpenGL"), std::string::npos) << e.what();
  }
  if (saved != nullptr) setenv("EGL_PLATFORM", saved, 1);
}
}  // namespace
}  // namespace skybake
