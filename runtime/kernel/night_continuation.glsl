// Kernel (data_formats/kernel/kernel_language.h): the night continuation
// of the tables below their lowest sun (runtime/physics/night_sky.h says what it
// models). Per channel the scale is x^p, x from here and the exponent p
// from the bake's irradiance table.

// x = 1 - tan(d / 2) / tan(span / 2) for a sun at zenith cosine mu_s a
// depression d below the lowest baked sun (zenith cosine edge_mu_s, sine
// edge_sin), clamped to [0, 1]: 0 from the dark angle on, span below the
// edge. tan(d / 2) = sin d / (1 + cos d) from the angle difference formulas,
// without an inverse cosine, whose GLSL implementations are too coarse here
// (a 2e-4 rad error is 0.7 % of the scale at Earth's fall-off). Meant for
// suns below the edge (mu_s < edge_mu_s).
SKYBAKE_KERNEL Real skybakeNightScaleBase(Real mu_s, Real edge_mu_s, Real edge_sin, Real inverse_tan_half_span) {
  Real mu = skybakeClampCosine(mu_s);
  Real sin_s = skybakeSafeSqrt(1.0 - mu * mu);
  Real sin_d = sin_s * edge_mu_s - mu * edge_sin;
  Real cos_d = mu * edge_mu_s + sin_s * edge_sin;
  return clamp(1.0 - sin_d / (1.0 + cos_d) * inverse_tan_half_span, 0.0, 1.0);
}
