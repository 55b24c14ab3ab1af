// In-memory tables. A 4D table is stored in its file atlas order: x = nu_index
// * mu_s_size + mu_s_index across, y = r_index * mu_size + mu_index down, so a
// bake writes and reads its memory without reshuffling.
#pragma once

#include <cstddef>
#include <vector>

#include "data_formats/spectra/spectrum.h"

namespace skybake {

struct Texture2D {
  int width = 0;   // mu (transmittance) or mu_s (irradiance)
  int height = 0;  // r
  std::vector<Spectrum> texels;

  Texture2D() = default;
  Texture2D(int w, int h) : width(w), height(h), texels(static_cast<size_t>(w) * h, Spectrum(0.0f)) {}
  size_t index(int x, int y) const { return static_cast<size_t>(y) * width + x; }
  Spectrum& at(int x, int y) { return texels[index(x, y)]; }
  const Spectrum& at(int x, int y) const { return texels[index(x, y)]; }
};

struct Texture4D {
  int r_size = 0;
  int mu_size = 0;
  int mu_s_size = 0;
  int nu_size = 0;
  std::vector<Spectrum> texels;

  Texture4D() = default;
  Texture4D(int r, int mu, int mu_s, int nu)
      : r_size(r),
        mu_size(mu),
        mu_s_size(mu_s),
        nu_size(nu),
        texels(static_cast<size_t>(r) * mu * mu_s * nu, Spectrum(0.0f)) {}
  int atlasWidth() const { return nu_size * mu_s_size; }
  int atlasHeight() const { return r_size * mu_size; }
  size_t index(int r, int mu, int mu_s, int nu) const {
    return ((static_cast<size_t>(r) * mu_size + mu) * nu_size + nu) * mu_s_size + mu_s;
  }
  Spectrum& at(int r, int mu, int mu_s, int nu) { return texels[index(r, mu, mu_s, nu)]; }
  const Spectrum& at(int r, int mu, int mu_s, int nu) const { return texels[index(r, mu, mu_s, nu)]; }
};

}  // namespace skybake
