// Colour error against the colour reference (colour_reference.h): per
// quantity and sun band, the relative error of luminance and the CIEDE2000
// difference of the colour, with the reference's own noise in both.
//
// CIELAB needs a white, and sky radiance spans ten decades. Each query is
// judged on its own: the method's XYZ and the reference's are scaled by the
// one factor that puts the reference's Y at L* = kComparedLightness under
// the sRGB white (D65, the white `skybake render`'s images are shown
// against). CIEDE2000 then measures the error of chromaticity and of
// lightness relative to the reference's, as an eye adapted to the patch's
// own brightness would see a patch of the bake beside a patch of the
// reference; absolute brightness is judged by the luminance error.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "baker/validation/colour_reference.h"
#include "baker/validation/validation.h"
#include "runtime/colour/spectral_to_xyz.h"
#include "runtime/sky.h"

namespace skybake {

// The lightness the reference of each query is scaled to: mid grey, where
// CIEDE2000's lightness weight S_L is 1 and a 1 % luminance error is about
// 0.22 units.
inline constexpr double kComparedLightness = 50.0;

// The low sun's last degree, sun zenith 89 to 90 deg, is reported again as
// its own band (kLastDegreeBand): there lookups start to integrate single
// scattering along the ray (Sky::singleScattering), which a colour bake
// does per wavelength, and a few bad values would hide in the low sun's
// whole band.
inline constexpr double kLastDegreeFromZenith_deg = 89.0;
inline constexpr const char* kLastDegreeBand = "sun_89_90";

// Reference Y below this (W m^-2 sr^-1, or W m^-2 for irradiance) is left
// out in `band`, as validate leaves out spectral values below
// smallestComparedValue(band): it is the Y of a flat spectrum of that value.
double smallestComparedY(SunBand band);

// A method's values as CIE XYZ. For a bake of wavelengths, its channels
// through the colour-matching functions by the rule `skybake render` uses
// (colour::SpectralToXyz: piecewise linear between the channels, end
// values held). The one place a bake's channels become a colour.
// `group_channels[g][i]` holds lane group g's lanes (Sky::laneGroup) at
// query i: a spectral bake's colour comes from all its groups' channels
// together, over all its wavelengths; any other bake has one group.
std::vector<colour::Xyz> bakeXyz(const Sky& sky, const std::vector<std::vector<Spectrum>>& group_channels);
// The same for a bake of one lane group.
std::vector<colour::Xyz> bakeXyz(const Sky& sky, const std::vector<Spectrum>& channels);

struct MethodXyz {
  std::vector<colour::Xyz> radiance;    // one per radiance query
  std::vector<colour::Xyz> irradiance;  // one per irradiance query; empty if the method has none
};
// Every lane group's values (evaluateLaneGroups) as XYZ.
MethodXyz bakeXyz(const Sky& sky, const std::vector<MethodValues>& group_values);

// CIEDE2000 between a colour and its reference after both are scaled by the
// factor that puts the reference at kComparedLightness.
double colourDifference(const colour::Xyz& value, const colour::Xyz& reference);

// The reference's own error in CIEDE2000 units at one query, one draw of
// it: the difference its half_difference (a draw of its error, with the
// true covariance of X, Y and Z) makes. Its median and 95th percentile over
// many queries are those of the reference's CIEDE2000 error.
double referenceColourError(const colour::Xyz& reference, const colour::Xyz& half_difference);

struct ColourErrorStats {
  int count = 0;                                    // queries compared
  int skipped = 0;                                  // reference Y below smallestComparedY(band)
  double luminance_rms = 0.0, luminance_p95 = 0.0;  // relative
  double ciede2000_median = 0.0, ciede2000_p95 = 0.0, ciede2000_max = 0.0;
  double reference_luminance_standard_error = 0.0;                         // RMS of the relative standard error of Y
  double reference_ciede2000_median = 0.0, reference_ciede2000_p95 = 0.0;  // referenceColourError
};

struct ColourErrorRow {
  std::string quantity;  // sky_radiance, ground_radiance, radiance_to_point, sky_irradiance
  std::string band;      // a sun band (validation_queries.h)
  ColourErrorStats stats;
};

struct ColourErrorReport {
  std::vector<double> reference_wavelengths_nm;
  int reference_paths = 0;
  std::vector<ColourErrorRow> rows;

  const ColourErrorRow* find(const std::string& quantity, const std::string& band) const;
  nlohmann::ordered_json toJson() const;
  std::string table() const;  // human-readable, one row per quantity and band
};

ColourErrorReport compareColourWithReference(const AtmosphereParameters& atmosphere, const QuerySet& queries,
                                             const ColourReferenceValues& reference, const MethodXyz& method,
                                             int reference_paths);

// The colour figures of a validation: the bake's, and those of the spectral
// reference at the bake's own wavelengths through the same conversion, a
// bake without any table error: what sampling the spectrum at those
// wavelengths costs (the floor the bake's figures cannot go below but by
// chance).
struct ColourValidation {
  ColourErrorReport bake;
  ColourErrorReport sampling;

  // The bake's report, with the sampling floor's rows as "sampling_errors".
  nlohmann::ordered_json toJson() const;
};

// `spectral_references` and `bakes`: one per lane group of the bake
// (lane_group_validation.h).
ColourValidation validateColour(const Sky& sky, const QuerySet& queries,
                                const std::vector<ReferenceValues>& spectral_references,
                                const ColourReferenceValues& colour_reference, const std::vector<MethodValues>& bakes,
                                int reference_paths);

}  // namespace skybake
