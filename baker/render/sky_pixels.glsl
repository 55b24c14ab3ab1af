// What each pixel of a sky image sees, in the GLSL library: the fragment
// stage of `skybake render --backend gl` (baker/render/gl_sky_image.cpp)
// and of the browser viewer's first pass (`skybake view`). The projections
// and what a pixel sees are directionAtImagePoint and radianceAlong of
// sky_image.cpp, per pixel centre: every channel of the bake (lanes past
// its channel count are 0). `skybake render` adds the sun disk afterwards
// on the CPU (sun_disk_pixels.h, exact over each pixel's area); the viewer
// defines SKYBAKE_RENDER_SUN_DISK and sets sun_disk_subsamples to count it
// here. Under an eclipse
// (SKYBAKE_RENDER_ECLIPSE defined: the eclipse lookups compile only for
// the images that need them) a first one-pixel draw (skylight_pass) gives
// the camera's skylight share, the same for every ray from a camera in the
// atmosphere, and the image's draws use it, as the CPU backend computes it
// once per image.
uniform vec2 image_size;          // pixels
uniform float strip_top_row;      // the first image row (from the top) of this draw
uniform float strip_rows;         // rows in this draw
uniform int projection;           // 0 fisheye, 1 latlong, 2 perspective
uniform float fov_rad;            // fisheye: full cone; perspective: unused (half sizes below)
uniform float sun_azimuth_rad;
uniform vec3 forward, right, up;  // perspective camera frame
uniform vec2 half_size;           // perspective: tan(fov / 2) across, times height / width down
uniform vec3 camera_m;
uniform vec3 sun_dir;
#ifdef SKYBAKE_RENDER_SUN_DISK
// The sun disk: 0 leaves it out; N > 0 counts it on N x N points of each
// pixel near the sun, each seeing the sun's radiance through the air along
// the pixel centre's ray.
uniform int sun_disk_subsamples;
#endif
#ifdef SKYBAKE_RENDER_ECLIPSE
uniform vec4 moon;                // centre (m from the planet's centre), radius (m)
uniform int skylight_pass;        // 1: this draw writes the camera's skylight share
uniform int camera_inside;        // 1: every ray starts at the camera, camera_skylight is its share
uniform vec4 camera_skylight;
#endif
layout(location = 0) out vec4 pixel;

vec3 fromZenithAzimuth(float zenith, float azimuth) {
  return vec3(sin(zenith) * cos(azimuth), sin(zenith) * sin(azimuth), cos(zenith));
}

bool pixelDirection(vec2 centre, out vec3 dir) {
  float u = centre.x / image_size.x;
  float w = centre.y / image_size.y;
  dir = vec3(0.0, 0.0, 1.0);
  if (projection == 1) {
    dir = fromZenithAzimuth(w * SKYBAKE_PI, sun_azimuth_rad + (u - 0.5) * 2.0 * SKYBAKE_PI);
    return true;
  }
  if (projection == 0) {
    float scale = min(image_size.x, image_size.y);
    float px = (2.0 * centre.x - image_size.x) / scale;
    float py = (image_size.y - 2.0 * centre.y) / scale;
    float rho = sqrt(px * px + py * py);
    if (rho > 1.0) return false;
    dir = fromZenithAzimuth(rho * fov_rad * 0.5, sun_azimuth_rad + atan(px, py));
    return true;
  }
  dir = normalize(forward + right * ((2.0 * u - 1.0) * half_size.x) + up * ((1.0 - 2.0 * w) * half_size.y));
  return true;
}

#ifdef SKYBAKE_RENDER_SUN_DISK
// The pixel's share of the sun disk times the sun's radiance through
// `transmittance`: the disk counted on sun_disk_subsamples^2 points of the
// pixel, only where its centre lies within the disk's radius plus twice
// the pixel's reach (centre to corner) of the sun. The points' directions
// step from the centre's by `across` and `down`, its change to the next
// pixel right and below (the projections bend too little within a pixel
// to matter at the sun disk's size: one direction computed per pixel).
#ifdef SKYBAKE_RENDER_ECLIPSE
vec4 sunDiskInPixel(vec3 dir, vec3 across, vec3 down, vec4 transmittance, SkybakeMoon m) {
#else
vec4 sunDiskInPixel(vec3 dir, vec3 across, vec3 down, vec4 transmittance) {
#endif
  float r = length(camera_m);
  if (skybakeRayIntersectsSphere(r, dot(camera_m, dir) / r, skybake_radii_m.x)) return vec4(0.0);  // the ground hides it
  float reach = 0.5 * (length(across) + length(down));
  if (acos(clamp(dot(dir, sun_dir), -1.0, 1.0)) > skybake_sun_disk.x + 2.0 * reach) return vec4(0.0);
  float n = float(sun_disk_subsamples);
  float covered = 0.0;
  for (int j = 0; j < sun_disk_subsamples; ++j) {
    for (int i = 0; i < sun_disk_subsamples; ++i) {
      vec2 offset = (vec2(float(i), float(j)) + 0.5) / n - 0.5;
      vec3 d = normalize(dir + across * offset.x + down * offset.y);
#ifdef SKYBAKE_RENDER_ECLIPSE
      if (skybakeInSunDiskPastMoon(camera_m, d, sun_dir, m)) covered += 1.0;
#else
      if (skybakeInSunDisk(d, sun_dir)) covered += 1.0;
#endif
    }
  }
  return skybakeSolarRadiance() * transmittance * (covered / (n * n));
}
#endif

void main() {
#ifdef SKYBAKE_RENDER_ECLIPSE
  SkybakeMoon eclipse_moon = SkybakeMoon(moon.xyz, moon.w);
  if (skylight_pass != 0) {
    pixel = skybakeEclipseSkylight(camera_m, sun_dir, eclipse_moon);
    return;
  }
#endif
  // Pixel centre in image coordinates, rows from the top.
  vec2 centre = vec2(gl_FragCoord.x, strip_top_row + (strip_rows - gl_FragCoord.y));
  vec3 dir;
  bool in_image = pixelDirection(centre, dir);
#ifdef SKYBAKE_RENDER_SUN_DISK
  // The direction's change to the next pixel right and below, taken where
  // every pixel still runs (derivatives need that); rows run downward in
  // the image, upward in gl_FragCoord.
  vec3 across = dFdx(dir);
  vec3 down = -dFdy(dir);
#endif
  if (!in_image) {
    pixel = vec4(0.0);
    return;
  }
  // What the pixel receives: sky and lit ground, or where the bake left
  // out ground irradiance (SKYBAKE_RENDER_SKY_ONLY defined) the air alone.
  // Chosen when compiling: the sky's lookup is most of the shader, and a
  // runtime choice between the two lookups would compile it twice.
  // (WebGL also refuses ?: between structs.)
#ifdef SKYBAKE_RENDER_ECLIPSE
  SkybakeRadianceAndTransmittance received;
#ifdef SKYBAKE_RENDER_SKY_ONLY
  if (camera_inside != 0) {
    received = skybakeSkyRadiance(camera_m, dir, sun_dir, eclipse_moon, camera_skylight);
  } else {
    received = skybakeSkyRadiance(camera_m, dir, sun_dir, eclipse_moon);
  }
#else
  if (camera_inside != 0) {
    received = skybakeReceivedRadiance(camera_m, dir, sun_dir, eclipse_moon, camera_skylight);
  } else {
    received = skybakeReceivedRadiance(camera_m, dir, sun_dir, eclipse_moon);
  }
#endif
#else
#ifdef SKYBAKE_RENDER_SKY_ONLY
  SkybakeRadianceAndTransmittance received = skybakeSkyRadiance(camera_m, dir, sun_dir);
#else
  SkybakeRadianceAndTransmittance received = skybakeReceivedRadiance(camera_m, dir, sun_dir);
#endif
#endif
  pixel = received.radiance;
#ifdef SKYBAKE_RENDER_SUN_DISK
  if (sun_disk_subsamples > 0) {
#ifdef SKYBAKE_RENDER_ECLIPSE
    pixel += sunDiskInPixel(dir, across, down, received.transmittance, eclipse_moon);
#else
    pixel += sunDiskInPixel(dir, across, down, received.transmittance);
#endif
  }
#endif
}
