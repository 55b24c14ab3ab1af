// Kernel (data_formats/kernel/kernel_language.h): the weights with which a
// lookup blends the tables' texels, the same on the CPU (runtime/
// table_sampler.h) and in the shaders (which read texels with texelFetch
// and blend them themselves: hardware filtering resolves its weights to
// 1/256 of a texel, which shows as bands where the tables change steeply).

// The ratios of two neighbouring texels between which a blend across the
// sun goes from linear to geometric (skybakeGeometricBlendShare).
#define SKYBAKE_GEOMETRIC_BLEND_RATIO 1.5
#define SKYBAKE_FULLY_GEOMETRIC_BLEND_RATIO 2.0

// Linear interpolation on an axis: the two neighbouring texels and the
// weight of the upper one.
struct SkybakeAxisLerp {
  int i0;
  int i1;
  Real w1;
};

// Positions outside the axis clamp to its ends; a NaN position (from a NaN
// query) is taken as the first texel, so no lookup indexes out of bounds.
SKYBAKE_KERNEL Real skybakeClampedAxisPosition(Real x, int size) { return x > 0.0 ? min(x, Real(size - 1)) : 0.0; }

// The texture coordinate u on an axis of `size` texels whose centres sit at
// (i + 0.5) / size.
SKYBAKE_KERNEL SkybakeAxisLerp skybakeAxisLerp(Real u, int size) {
  Real x = skybakeClampedAxisPosition(u * Real(size) - 0.5, size);
  SkybakeAxisLerp lerp;
  lerp.i0 = min(int(x), max(size - 2, 0));
  lerp.i1 = min(lerp.i0 + 1, size - 1);
  lerp.w1 = x - Real(lerp.i0);
  return lerp;
}

// The nu axis, whose texels sit at i / (size - 1): both ends tabulated.
SKYBAKE_KERNEL SkybakeAxisLerp skybakeAxisLerpNu(Real u_nu, int size) {
  Real x = skybakeClampedAxisPosition(u_nu * Real(size - 1), size);
  SkybakeAxisLerp lerp;
  lerp.i0 = min(int(x), size - 2);
  lerp.i1 = lerp.i0 + 1;
  lerp.w1 = x - Real(lerp.i0);
  return lerp;
}

// a^(1-w) b^w for positive a and b, in logarithms: the ratio b / a of a
// normal and a denormal number (thick or dark atmospheres reach 1e-40)
// overflows, and a (b / a)^w then gives inf or NaN.
SKYBAKE_KERNEL Real skybakeGeometricBlend(Real a, Real b, Real w) { return exp((1.0 - w) * log(a) + w * log(b)); }

// Across mu_s and nu with the sun below the horizon the sky dims by orders
// of magnitude per degree, roughly exponentially, and a linear blend of two
// texels that far apart overestimates it by tens of percent; a geometric
// one is exact for exponential fall-off. Neighbours closer than
// SKYBAKE_GEOMETRIC_BLEND_RATIO are blended linearly (the blends then
// differ by < 1 % and the pow is saved), from
// SKYBAKE_FULLY_GEOMETRIC_BLEND_RATIO on geometrically, and between the two
// with this share of the geometric blend: smooth in the ratio, since a
// switch at one ratio made lookups step by up to 2 % as the sun moved.
// `ratio` >= 1 (infinite for a denormal beside a normal number).
SKYBAKE_KERNEL Real skybakeGeometricBlendShare(Real ratio) {
  Real x = clamp((ratio - SKYBAKE_GEOMETRIC_BLEND_RATIO) /
                     (SKYBAKE_FULLY_GEOMETRIC_BLEND_RATIO - SKYBAKE_GEOMETRIC_BLEND_RATIO),
                 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

// Two texels blended with weight w of b: geometrically where both are
// positive and far apart, by skybakeGeometricBlendShare's share, else
// linearly. As a weighted sum, not linear + (geometric - linear) share: with
// a denormal neighbour the difference cancels the geometric blend away.
SKYBAKE_KERNEL Real skybakeBlendGeometricWhereSteep(Real a, Real b, Real w) {
  Real linear_blend = a + (b - a) * w;
  if (a > 0.0 && b > 0.0 && (b > SKYBAKE_GEOMETRIC_BLEND_RATIO * a || a > SKYBAKE_GEOMETRIC_BLEND_RATIO * b)) {
    Real share = skybakeGeometricBlendShare(a > b ? a / b : b / a);
    return linear_blend * (1.0 - share) + skybakeGeometricBlend(a, b, w) * share;
  }
  return linear_blend;
}

// Two texels blended with weight w of b: geometrically by `geometric_share`
// (in [0, 1]) where both are positive, else linearly. The irradiance table
// blends so across r (irradiance falls off with altitude roughly
// exponentially) and across the sun texels below the horizon.
SKYBAKE_KERNEL Real skybakeBlendGeometricWherePositive(Real a, Real b, Real w, Real geometric_share) {
  Real linear_blend = a + (b - a) * w;
  if (a > 0.0 && b > 0.0) return linear_blend * (1.0 - geometric_share) + skybakeGeometricBlend(a, b, w) * geometric_share;
  return linear_blend;
}

// The part below the horizon of the irradiance table's sun interval that
// ends at texel i1, the horizon sitting at texel position horizon_texel:
// the interval holding the horizon is blended geometrically in proportion,
// so that the lookup is continuous for any table size.
SKYBAKE_KERNEL Real skybakeBelowHorizonShare(Real horizon_texel, int i1) {
  return clamp(1.0 + horizon_texel - Real(i1), 0.0, 1.0);
}
