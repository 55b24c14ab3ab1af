// The sun texels of one (r, mu) row of a 4D table, as the ray-integrating
// stages (single and multiple scattering) loop over them.
#pragma once

#include <vector>

#include "data_formats/parameterization/texture_mapping.h"

namespace skybake {

// mu_s at the centre of each mu_s texel (the same for every row).
inline std::vector<double> scatteringTexelMuS(const AtmosphereDomain& d, const ScatteringSizes& s) {
  std::vector<double> mu_s(s.mu_s);
  for (int i = 0; i < s.mu_s; ++i) mu_s[i] = muSFromScatteringTexel(d, s, i);
  return mu_s;
}

// The distinct sun texels of a row. Slices whose nu, clamped to what the
// row's mu and the texel's mu_s allow, equals the slice before's describe the
// same geometry (every slice does at mu = -1 and 1): computed once, stored
// into slices first_nu .. last_nu. The cosines are arrays, which loops over
// the row's suns vectorize over.
struct RowSunTexels {
  struct Slices {
    int i_mu_s, first_nu, last_nu;
  };
  std::vector<Slices> slices;
  std::vector<double> mu_s, nu;

  size_t size() const { return slices.size(); }

  void collect(const ScatteringSizes& s, const std::vector<double>& texel_mu_s, double mu) {
    slices.clear();
    mu_s.clear();
    nu.clear();
    for (int i_mu_s = 0; i_mu_s < s.mu_s; ++i_mu_s) {
      for (int i_nu = 0; i_nu < s.nu; ++i_nu) {
        const double sun_nu = clampNu(nuOfScatteringSlice(i_nu, s.nu), mu, texel_mu_s[i_mu_s]);
        if (i_nu > 0 && sun_nu == nu.back()) {
          ++slices.back().last_nu;
          continue;
        }
        slices.push_back({i_mu_s, i_nu, i_nu});
        mu_s.push_back(texel_mu_s[i_mu_s]);
        nu.push_back(sun_nu);
      }
    }
  }
};

}  // namespace skybake
