// Kernel (data_formats/kernel/kernel_language.h): phase functions, sr^-1,
// normalised to 1 over the sphere. nu is the cosine of the scattering angle
// (between the propagation directions before and after).

// Rayleigh: 3 / (16 pi) (1 + nu^2). The shape (1 + nu^2) alone serves the
// bake's density kernel, which expands it in Fourier modes and applies the
// normalisation after.
#define SKYBAKE_RAYLEIGH_PHASE_NORMALISATION (3.0 / (16.0 * SKYBAKE_PI))
SKYBAKE_KERNEL Real skybakeRayleighPhaseShape(Real nu) { return 1.0 + nu * nu; }
SKYBAKE_KERNEL Real skybakeRayleighPhase(Real nu) {
  return SKYBAKE_RAYLEIGH_PHASE_NORMALISATION * skybakeRayleighPhaseShape(nu);
}

// Cornette-Shanks: Henyey-Greenstein's shape with Rayleigh's (1 + nu^2), a
// better fit to Mie scattering by haze. Its normalisation,
// 3 / (8 pi) (1 - g^2) / (2 + g^2), depends on g only, so callers work it
// out once per g. |g| < 1 is guaranteed by validation, so the base
// 1 + g^2 - 2 g nu >= (1 - |g|)^2 > 0.
SKYBAKE_KERNEL Real skybakeCornetteShanksNormalisation(Real g) {
  return 3.0 / (8.0 * SKYBAKE_PI) * (1.0 - g * g) / (2.0 + g * g);
}
SKYBAKE_KERNEL Real skybakeCornetteShanksShape(Real g, Real nu) {
  Real base = 1.0 + g * g - 2.0 * g * nu;
  return skybakeRayleighPhaseShape(nu) / (base * sqrt(base));
}
SKYBAKE_KERNEL Real skybakeCornetteShanksPhase(Real g, Real normalisation, Real nu) {
  Real base = 1.0 + g * g - 2.0 * g * nu;
  return normalisation * skybakeRayleighPhaseShape(nu) / (base * sqrt(base));
}
