// Kernel (data_formats/kernel/kernel_language.h): the density of a
// constituent at an altitude, relative to where its coefficients are
// quoted (density 1). A profile is layers stacked from the ground up, the
// last reaching the top whatever its width; within a layer the density is
// this formula (CONFIG.md's [atmosphere] density layers).

// Dimensionless density in [0, 1] at altitude_m above the ground in a layer
// of terms exp_term exp(exp_scale_per_m h) + linear_term_per_m h +
// constant_term.
SKYBAKE_KERNEL Real skybakeLayerDensity(Real exp_term, Real exp_scale_per_m, Real linear_term_per_m,
                                        Real constant_term, Real altitude_m) {
  Real value = exp_term * exp(exp_scale_per_m * altitude_m) + linear_term_per_m * altitude_m + constant_term;
  return clamp(value, 0.0, 1.0);
}
