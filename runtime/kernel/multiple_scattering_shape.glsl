// Kernel (data_formats/kernel/kernel_language.h): the shape that multiple
// scattering is stored divided by, f = (1 - w) / (4 pi) + w peak, per
// channel, sr^-1 (runtime/physics/multiple_scattering_phase.h says why).

// The broad part: isotropic.
#define SKYBAKE_BROAD_PHASE (1.0 / (4.0 * SKYBAKE_PI))

// Mie's share of scattering from the Rayleigh and Mie scattering
// coefficients times their amounts (densities or their integrals); 0 where
// nothing scatters (any positive divisor will do there).
SKYBAKE_KERNEL Real skybakeMieShare(Real rayleigh, Real mie) {
  Real total = rayleigh + mie;
  return total > 0.0 ? mie / total : 0.0;
}

// f for the peak weight w in [0, 1] and the peak's phase function value.
SKYBAKE_KERNEL Real skybakeMultipleShapeWithPeak(Real peak_weight, Real peak) {
  return SKYBAKE_BROAD_PHASE + peak_weight * (peak - SKYBAKE_BROAD_PHASE);
}
