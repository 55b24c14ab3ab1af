// The colour reference: CIE XYZ of the reference's radiance and sky
// irradiance from 41 wavelengths, 380 to 780 nm every 10 nm, the atmosphere
// at those wavelengths read from the config's own spectra
// (configAtWavelengths), so a bake of a few wavelengths is judged against
// the colour an eye would see, not against its own channels.
//
// The 41 wavelengths are split into kColourWavelengthGroups groups of at
// most 4 (a reference solve holds 4 channels), group g holding wavelengths
// g, g + 11, g + 22 and g + 33: each group spans the visible spectrum, as a
// hero wavelength with its rotated companions does. Single scattering is
// integrated deterministically for every group. The higher orders' XYZ is
// estimated with the paths of one spectral reference shared among the
// groups (each group traces paths / 11 of them, each path weighting its 4
// wavelengths by their colour-matching weights): an unbiased estimate of
// the 41-wavelength XYZ for the cost of a 4-channel reference, whose noise
// in XYZ is about that of one channel with all the paths. The paths are
// traced as two independent halves, A and B, the estimate their mean:
// (A - B) / 2 is then a draw of the estimate's own error, with its true
// covariance across X, Y and Z, so the reference's noise in CIEDE2000 units
// is measured, not modelled (docs/COLOUR.md).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>

#include "baker/reference/lit_air_guide.h"
#include "baker/reference/reference_solver.h"
#include "baker/stages/progress.h"
#include "baker/validation/reference_cache.h"
#include "baker/validation/validation.h"
#include "baker/validation/validation_queries.h"
#include "data_formats/config/atmosphere_parameters.h"

namespace skybake {

inline constexpr double kColourReferenceFirst_nm = 380.0;
inline constexpr double kColourReferenceLast_nm = 780.0;
inline constexpr int kColourReferenceWavelengthCount = 41;  // every 10 nm
// 41 wavelengths in groups of at most 4 channels.
inline constexpr int kColourWavelengthGroups = (kColourReferenceWavelengthCount + kMaxChannels - 1) / kMaxChannels;

struct ColourReferenceAtmospheres {
  std::vector<double> wavelengths_nm;          // 380, 390, ..., 780
  std::vector<AtmosphereParameters> groups;    // group g: wavelengths g, g + G, g + 2G, ...
  std::vector<glm::dmat4> group_lanes_to_xyz;  // column c: X, Y, Z (nm) of one unit of channel c
  // The reference's guide toward twilight light, made from the first group
  // (its wavelengths span 380 to 780 nm) and shared by every solver of
  // every group: its tables are computed once, not once per group and
  // query. A guide only shapes where paths go, so one made for other
  // wavelengths leaves each group's estimate unbiased.
  std::shared_ptr<LitAirGuide> guide;
};

// The config's atmosphere at the 41 wavelengths. Throws Error(BadInput)
// naming the key for a config that cannot give spectra there (a list of
// differing values, a spectrum file that stops short of 380 or 780 nm).
ColourReferenceAtmospheres colourReferenceAtmospheres(std::string_view toml_text, const std::string& source,
                                                      const std::filesystem::path& spectrum_directory);
ColourReferenceAtmospheres colourReferenceAtmospheresFromFile(const std::filesystem::path& config_path);

// Refuses (Error(BadInput)) a config that is not the one the bake was made
// from: read at the bake's own wavelengths, its atmosphere must be the
// bake's, value for value (the lowest tabulated sun aside, which the bake
// may have settled).
// A spectral bake (more than 4 wavelengths) is checked lane group by lane
// group: `lane_groups` are its groups' atmospheres (BakeContents::lane_groups).
void requireConfigOfBake(const std::filesystem::path& config_path, const AtmosphereParameters& bake,
                         const std::vector<AtmosphereParameters>& lane_groups = {});

// The paths each group traces in each half for a reference of `paths`
// paths: a share, at least one per replicate.
int colourGroupHalfPaths(int paths);

// XYZ (in x, y, z; w is 0) of one query's reference, W m^-2 sr^-1 for
// radiance and W m^-2 for irradiance.
struct ColourEstimate {
  SpectrumD value;            // (A + B) / 2
  SpectrumD standard_error;   // from the replicates of both halves
  SpectrumD half_difference;  // (A - B) / 2: a draw of the error of `value`
};
ColourEstimate colourRadianceReference(const ColourReferenceAtmospheres& colour, const ReferenceRay& ray, int paths,
                                       uint64_t seed, const Moon& moon = Moon{});
ColourEstimate colourSkyIrradianceReference(const ColourReferenceAtmospheres& colour, const glm::dvec3& point,
                                            const glm::dvec3& sun, int paths, uint64_t seed, const Moon& moon = Moon{});

struct ColourReferenceValues {
  // XYZ per radiance query, with its half_difference (transmittance unused)
  std::vector<CachedReference> radiance;
  std::vector<CachedReference> irradiance;
  double seconds = 0.0;
  int computed = 0;
  int cached = 0;
};

// The colour reference for every query of the set, from its cache where it
// holds them (ReferenceCache's colour directory; keys "xyz " and the
// spectral reference's key), the rest computed in parallel and cached.
ColourReferenceValues computeColourReference(const ColourReferenceAtmospheres& colour, const QuerySet& queries,
                                             const ReferenceSettings& settings, ProgressSink& progress);

}  // namespace skybake
