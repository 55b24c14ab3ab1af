// The CIE 1931 standard colorimetric observer (2 degree field): the
// colour-matching functions xbar, ybar, zbar tabulated every 5 nm from 360 to
// 830 nm, as published in CIE 015:2018 "Colorimetry", 4th edition, and in
// ISO/CIE 11664-1:2019 "Colorimetry - Part 1: CIE standard colorimetric
// observers". The values are the published five-digit table, unchanged.
#pragma once

#include <array>

namespace skybake::colour {

struct ColourMatchingSample {
  double wavelength_nm;
  double xbar, ybar, zbar;  // dimensionless; ybar is the photopic luminous efficiency V(lambda)
};

// Spacing of the published table.
inline constexpr double kCie1931Step_nm = 5.0;
inline constexpr int kCie1931SampleCount = 95;  // 360, 365, ..., 830 nm

// The table, in increasing wavelength.
const std::array<ColourMatchingSample, kCie1931SampleCount>& cie1931Observer();

}  // namespace skybake::colour
