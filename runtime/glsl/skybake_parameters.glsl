// skybake GLSL library (README.md gives the files' order): what a bake gives the shader.
//
// The library is these five files concatenated in order (parameters,
// geometry, tables, integrals, sky), after the defines that
// skybake::gl::skyGlslDefines() generates from the C++ constants
// (SKYBAKE_GAUSS_ABSCISSA, SKYBAKE_MAX_DENSITY_LAYERS, ...). Every value that
// depends on the bake comes from the uniform block below, which
// skybake::gl::SkyGlResources fills from a loaded Sky, and from six
// textures holding the tables as the file lays them out. GLSL 3.30 core /
// GLSL ES 3.00: the including shader supplies the #version line (and, for
// ES, default precisions for float, int, sampler2D and sampler3D).
//
// Units: metres, radians as cosines, radiance W m^-2 sr^-1 nm^-1, irradiance
// W m^-2 nm^-1. A vec4 spectrum holds one lane per channel of the bake in its
// channel order (skybake_wavelengths_nm); unused lanes are 0.

// Vulkan and other targets need explicit bindings; OpenGL 3.3 takes them from
// glUniformBlockBinding and glUniform1i, which SkyGlResources calls.
#ifndef SKYBAKE_UNIFORM_BLOCK_LAYOUT
#define SKYBAKE_UNIFORM_BLOCK_LAYOUT layout(std140)
#endif
#ifndef SKYBAKE_SAMPLER_LAYOUT
#define SKYBAKE_SAMPLER_LAYOUT(unit)
#endif

// The layout is mirrored by skybake::gl::SkyUniformBlock (sky_gl_parameters.h).
SKYBAKE_UNIFORM_BLOCK_LAYOUT uniform SkybakeAtmosphere {
  // x bottom (ground) radius, y top radius, z H = sqrt(top^2 - bottom^2),
  // w the sun's angular radius (rad).
  vec4 skybake_radii_m;
  // The 4D tables' domain: x, y rho (distance to the horizon, m) at the r
  // axis's first and last texel; z the unit sun coordinate at the mu_s axis's
  // first texel, w one over its span (0 where the span is empty).
  vec4 skybake_scattering_domain;
  // The unit sun coordinate's constants: x d_min (m), y 1 / (d_max - d_min)
  // (m^-1), z 1 / A, w 1 (0 where the sun range is empty).
  vec4 skybake_mu_s_map;
  // The split of the sun axis at the horizon (SunAxisMapping): x the share of
  // the axis below the horizon (0: Bruneton's coordinate alone), y that
  // coordinate at the horizon, z 1 / mu_s_min, w the spacing c at the
  // horizon (SunBelowHorizonAxis).
  vec4 skybake_mu_s_below;
  // x, y: the lowest and highest baked sun as zenith cosines (a sun outside
  // is integrated at the nearest; x is -1, the nadir, where the tables go on
  // to every sun); z Mie phase g, w the multiple-scattering shape's g_ms.
  vec4 skybake_sun_angles;
  // x, y: Cornette-Shanks normalisations (sr^-1) for g and g_ms; z the squared
  // chord |view - sun|^2 of the sun disk's edge, 4 sin^2(radius / 2).
  vec4 skybake_phase;
  ivec4 skybake_scattering_size;  // 4D radiance tables: r, mu, mu_s, nu texels (the density: its own mu)
  ivec4 skybake_table_2d_size;    // optical depth mu, r; irradiance mu_s, r texels
  // 1 or 0: x the mu axis holds rays to the ground; which tables the file
  // has: y single Mie, z multiple-scattering density, w irradiance.
  ivec4 skybake_parts;
  // 1 or 0: x the bake offers radiance to points, y ground irradiance
  // ([scene] outputs); z channel count; w what the channels hold, 0
  // wavelengths (W m^-2 sr^-1 nm^-1), 1 CIE X, Y, Z (W m^-2 sr^-1).
  ivec4 skybake_outputs;
  ivec4 skybake_profile_layers;  // layers of the Rayleigh, Mie, absorption profiles
  vec4 skybake_sun_irradiance;         // at the top of the atmosphere, W m^-2 nm^-1
  vec4 skybake_solar_radiance;         // of the sun disk above the atmosphere, W m^-2 sr^-1 nm^-1
  vec4 skybake_rayleigh_scattering;    // m^-1 at density 1
  vec4 skybake_mie_scattering;         // m^-1 at density 1
  vec4 skybake_mie_extinction;         // m^-1 at density 1
  vec4 skybake_absorption_extinction;  // m^-1 at density 1
  vec4 skybake_ground_albedo;          // Lambertian, dimensionless
  vec4 skybake_column_mie_share_power; // m_column^2 of the multiple-scattering shape, per channel
  vec4 skybake_wavelengths_nm;         // each lane's wavelength, 0 for unused lanes and X, Y, Z
  // The night continuation below the lowest baked sun (skybakeNightScale):
  // x its zenith cosine, y its zenith sine, z one over tan(span / 2), the
  // span being the depression over which the scale falls to 0, w 1 where the
  // 4D tables' sun axis reaches it (0: a narrowed scene's tables, clamped
  // instead).
  vec4 skybake_night;
  vec4 skybake_night_exponent;         // the scale's power per channel
  // cd m^-2 per unit of each channel: (0, 683, 0, 0) for X, Y, Z, the CIE
  // 1931 ybar weights of the wavelengths times 683 lm/W otherwise
  // (skybakeLuminance, Sky::luminanceWeights).
  vec4 skybake_luminance_weights;
  // Density layers, SKYBAKE_MAX_DENSITY_LAYERS per profile (Rayleigh, Mie,
  // absorption): width (m), exp_term, exp_scale (m^-1), linear_term (m^-1);
  // and in skybake_layer_constant[i].x the constant term.
  vec4 skybake_layer_shape[3 * SKYBAKE_MAX_DENSITY_LAYERS];
  vec4 skybake_layer_constant[3 * SKYBAKE_MAX_DENSITY_LAYERS];
};

// The tables, read with texelFetch only (the library interpolates itself,
// with the CPU's weights). 2D: x = mu (or mu_s), y = r, RGBA32F. 4D tables
// are 3D textures of the file's atlas: x = nu * mu_s_size + mu_s, y = mu,
// z = r, as half floats (RGB16F, RGBA16F for 4 channels) each texel of which
// is its value over its (r, mu_s) slice's scale, or RGBA32F with scales of 1
// (runtime/gpu_tables.h). A table the file leaves out is a 1-texel texture
// of zeros.
SKYBAKE_SAMPLER_LAYOUT(1) uniform sampler2D skybake_optical_depth;      // dimensionless, to the top
SKYBAKE_SAMPLER_LAYOUT(2) uniform sampler3D skybake_single_rayleigh;    // W m^-2 nm^-1 (over the phase)
SKYBAKE_SAMPLER_LAYOUT(3) uniform sampler3D skybake_single_mie;         // W m^-2 nm^-1 (over the phase)
SKYBAKE_SAMPLER_LAYOUT(4) uniform sampler3D skybake_multiple_scattering;  // W m^-2 nm^-1 (over the shape)
SKYBAKE_SAMPLER_LAYOUT(5) uniform sampler3D skybake_multiple_density;   // W m^-3 nm^-1 (over the shape)
SKYBAKE_SAMPLER_LAYOUT(6) uniform sampler2D skybake_irradiance;         // W m^-2 nm^-1, horizontal surface
// The 4D tables' slice scales, RGBA32F, x = mu_s, y = r: lane
// SKYBAKE_SCALE_* of a texel is that table's scale in slice (r, mu_s).
SKYBAKE_SAMPLER_LAYOUT(7) uniform sampler2D skybake_slice_scales;
#define SKYBAKE_SCALE_SINGLE_RAYLEIGH 0
#define SKYBAKE_SCALE_SINGLE_MIE 1
#define SKYBAKE_SCALE_MULTIPLE_SCATTERING 2
#define SKYBAKE_SCALE_MULTIPLE_DENSITY 3

// Radiance (W m^-2 sr^-1 nm^-1) and transmittance (dimensionless) along one path.
struct SkybakeRadianceAndTransmittance {
  vec4 radiance;
  vec4 transmittance;
};

// Direct sun and scattered sky irradiance on a surface, W m^-2 nm^-1.
struct SkybakeSunAndSkyIrradiance {
  vec4 sun;
  vec4 sky;
};
