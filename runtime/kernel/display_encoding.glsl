// Kernel (data_formats/kernel/kernel_language.h): how skybake shows linear
// light on a display. `skybake render`'s PNG (baker/render/sky_image.cpp),
// the browser viewer (`skybake view`) and a renderer's own shaders encode a
// linear sRGB value the same way: times the exposure, tone-mapped, then the
// sRGB transfer function (IEC 61966-2-1:1999), clamped to [0, 1].

// The tone maps, as SKYBAKE_TONE_MAP_* values.
#define SKYBAKE_TONE_MAP_NONE 0
#define SKYBAKE_TONE_MAP_REINHARD 1
#define SKYBAKE_TONE_MAP_ACES 2
// Where the sRGB standard's linear segment near black meets its power
// curve, in linear light.
#define SKYBAKE_SRGB_LINEAR_SEGMENT_END 0.0031308

// Linear light, clamped to [0, 1] (a display shows nothing outside it), to
// the encoded sRGB value in [0, 1].
SKYBAKE_KERNEL Real skybakeSrgbEncode(Real linear) {
  Real v = clamp(linear, 0.0, 1.0);
  return v <= SKYBAKE_SRGB_LINEAR_SEGMENT_END ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

// Narkowicz's fit of the ACES filmic curve, in [0, 1].
SKYBAKE_KERNEL Real skybakeAcesFilm(Real x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// A linear sRGB component times `exposure`, tone-mapped by `tone_map`
// (SKYBAKE_TONE_MAP_*), sRGB-encoded: the display value in [0, 1]. A
// negative component (a colour outside the sRGB gamut) shows as 0.
SKYBAKE_KERNEL Real skybakeDisplayValue(Real linear, Real exposure, int tone_map) {
  Real v = max(linear * exposure, 0.0);
  if (tone_map == SKYBAKE_TONE_MAP_REINHARD) v = v / (1.0 + v);
  if (tone_map == SKYBAKE_TONE_MAP_ACES) v = skybakeAcesFilm(v);
  return skybakeSrgbEncode(v);
}
