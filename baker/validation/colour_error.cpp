#include "baker/validation/colour_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <span>

#include <fmt/format.h>

#include "runtime/colour/ciede2000.h"
#include "runtime/colour/cielab.h"

namespace skybake {
namespace {

colour::Xyz xyzOf(const SpectrumD& s) { return {s.x, s.y, s.z}; }

colour::Xyz scaled(const colour::Xyz& c, double factor) { return {c.x * factor, c.y * factor, c.z * factor}; }

// Y / Yn of L* = kComparedLightness (the cube-root branch of CIELAB).
double comparedRelativeLuminance() {
  const double f = (kComparedLightness + 16.0) / 116.0;
  return f * f * f;
}

// The order rows come in: the quantities as validate's spectral table, then
// the sun bands in their enum's order.
int quantityOrder(const std::string& quantity) {
  static const char* kOrder[] = {"sky_radiance", "ground_radiance", "radiance_to_point", "sky_irradiance"};
  for (int i = 0; i < 4; ++i) {
    if (quantity == kOrder[i]) return i;
  }
  return 4;
}

struct Samples {
  std::vector<double> luminance_errors, ciede2000, reference_luminance_errors, reference_ciede2000;
  int skipped = 0;
};

// Nearest-rank quantile of sorted values.
double quantile(const std::vector<double>& sorted, double q) {
  return sorted[static_cast<size_t>(std::max(std::ceil(q * sorted.size()), 1.0)) - 1];
}

double rms(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v * v;
  return std::sqrt(sum / values.size());
}

ColourErrorStats summarize(Samples s) {
  ColourErrorStats e;
  e.count = static_cast<int>(s.ciede2000.size());
  e.skipped = s.skipped;
  if (s.ciede2000.empty()) return e;
  for (auto* v : {&s.luminance_errors, &s.ciede2000, &s.reference_ciede2000}) std::sort(v->begin(), v->end());
  e.luminance_rms = rms(s.luminance_errors);
  e.luminance_p95 = quantile(s.luminance_errors, 0.95);
  e.ciede2000_median = quantile(s.ciede2000, 0.5);
  e.ciede2000_p95 = quantile(s.ciede2000, 0.95);
  e.ciede2000_max = s.ciede2000.back();
  e.reference_luminance_standard_error = rms(s.reference_luminance_errors);
  e.reference_ciede2000_median = quantile(s.reference_ciede2000, 0.5);
  e.reference_ciede2000_p95 = quantile(s.reference_ciede2000, 0.95);
  return e;
}

}  // namespace

double smallestComparedY(SunBand band) { return smallestComparedValue(band) * colour::ybarIntegral_nm(); }

std::vector<colour::Xyz> bakeXyz(const Sky& sky, const std::vector<std::vector<Spectrum>>& group_channels) {
  std::vector<colour::Xyz> out;
  if (group_channels.empty()) return out;
  const size_t queries = group_channels.front().size();
  out.reserve(queries);
  if (sky.atmosphere().storesCieXyz()) {
    // A colour bake's channels are X, Y, Z already (integrated while it baked).
    for (const Spectrum& s : group_channels.front()) out.push_back({s.x, s.y, s.z});
    return out;
  }
  const colour::SpectralToXyz to_xyz(sky.atmosphere().wavelengths_nm);
  std::vector<float> channels(static_cast<size_t>(sky.channelCount()));
  for (size_t i = 0; i < queries; ++i) {
    // Query i's values of every lane group, joined into the bake's channels.
    sky.writeEveryChannel([&](const Sky&, int g) { return group_channels.at(static_cast<size_t>(g)).at(i); },
                          std::array{channels.data()});
    out.push_back(to_xyz(std::span<const float>(channels)));
  }
  return out;
}

std::vector<colour::Xyz> bakeXyz(const Sky& sky, const std::vector<Spectrum>& channels) {
  return bakeXyz(sky, std::vector<std::vector<Spectrum>>{channels});
}

MethodXyz bakeXyz(const Sky& sky, const std::vector<MethodValues>& group_values) {
  std::vector<std::vector<Spectrum>> radiance, irradiance;
  for (const MethodValues& v : group_values) {
    radiance.push_back(v.radiance);
    irradiance.push_back(v.irradiance);
  }
  return {bakeXyz(sky, radiance), bakeXyz(sky, irradiance)};
}

double colourDifference(const colour::Xyz& value, const colour::Xyz& reference) {
  const double factor = comparedRelativeLuminance() / reference.y;
  const colour::Xyz white = colour::srgbWhiteXyz();
  return colour::ciede2000(colour::labFromXyz(scaled(value, factor), white),
                           colour::labFromXyz(scaled(reference, factor), white));
}

double referenceColourError(const colour::Xyz& reference, const colour::Xyz& half_difference) {
  return colourDifference(
      {reference.x + half_difference.x, reference.y + half_difference.y, reference.z + half_difference.z}, reference);
}

ColourErrorReport compareColourWithReference(const AtmosphereParameters& a, const QuerySet& queries,
                                             const ColourReferenceValues& reference, const MethodXyz& method,
                                             int reference_paths) {
  ColourErrorReport report;
  report.reference_paths = reference_paths;
  for (int k = 0; k < kColourReferenceWavelengthCount; ++k) {
    report.reference_wavelengths_nm.push_back(kColourReferenceFirst_nm +
                                              k * (kColourReferenceLast_nm - kColourReferenceFirst_nm) /
                                                  (kColourReferenceWavelengthCount - 1));
  }
  // (quantity, row) order; row 2 * band, and the last degree's after the low sun's.
  std::map<std::pair<int, int>, std::pair<std::string, Samples>> samples;
  const int last_degree_row = 2 * static_cast<int>(SunBand::LowSun) + 1;
  auto addToRow = [&](const std::string& quantity, int row, SunBand band, const colour::Xyz& value,
                      const CachedReference& r) {
    auto& [name, s] = samples[{quantityOrder(quantity), row}];
    name = quantity;
    const colour::Xyz ref = xyzOf(r.value);
    if (!(ref.y >= smallestComparedY(band))) {
      ++s.skipped;
      return;
    }
    s.luminance_errors.push_back(std::abs(value.y - ref.y) / ref.y);
    s.ciede2000.push_back(colourDifference(value, ref));
    s.reference_luminance_errors.push_back(r.standard_error.y / ref.y);
    s.reference_ciede2000.push_back(referenceColourError(ref, xyzOf(r.half_difference)));
  };
  auto add = [&](const std::string& quantity, double sun_zenith_deg, const colour::Xyz& value,
                 const CachedReference& r) {
    const SunBand band = sunBand(sun_zenith_deg);
    addToRow(quantity, 2 * static_cast<int>(band), band, value, r);
    if (band == SunBand::LowSun && sun_zenith_deg >= kLastDegreeFromZenith_deg) {
      addToRow(quantity, last_degree_row, band, value, r);
    }
  };
  for (size_t i = 0; i < queries.radiance.size(); ++i) {
    const std::string quantity = radianceQuantity(a, queries.radiance[i]);
    if (quantity.empty()) continue;
    add(quantity, queries.radiance[i].sun_zenith_deg, method.radiance[i], reference.radiance[i]);
  }
  if (!method.irradiance.empty()) {
    for (size_t i = 0; i < queries.irradiance.size(); ++i) {
      add("sky_irradiance", queries.irradiance[i].sun_zenith_deg, method.irradiance[i], reference.irradiance[i]);
    }
  }
  for (const auto& [order, entry] : samples) {
    const char* band =
        order.second == last_degree_row ? kLastDegreeBand : sunBandName(static_cast<SunBand>(order.second / 2));
    report.rows.push_back({entry.first, band, summarize(entry.second)});
  }
  return report;
}

namespace {

std::vector<Spectrum> referenceChannels(const std::vector<CachedReference>& reference) {
  std::vector<Spectrum> out;
  out.reserve(reference.size());
  for (const CachedReference& r : reference) out.push_back(Spectrum(r.value));
  return out;
}

}  // namespace

ColourValidation validateColour(const Sky& sky, const QuerySet& queries,
                                const std::vector<ReferenceValues>& spectral_references,
                                const ColourReferenceValues& colour_reference, const std::vector<MethodValues>& bakes,
                                int reference_paths) {
  const AtmosphereParameters& a = sky.atmosphere();
  std::vector<std::vector<Spectrum>> radiance, irradiance;
  for (const ReferenceValues& r : spectral_references) {
    radiance.push_back(referenceChannels(r.radiance));
    irradiance.push_back(referenceChannels(r.irradiance));
  }
  MethodXyz sampled{bakeXyz(sky, radiance), {}};
  if (!bakes.front().irradiance.empty()) sampled.irradiance = bakeXyz(sky, irradiance);
  return {compareColourWithReference(a, queries, colour_reference, bakeXyz(sky, bakes), reference_paths),
          compareColourWithReference(a, queries, colour_reference, sampled, reference_paths)};
}

nlohmann::ordered_json ColourValidation::toJson() const {
  nlohmann::ordered_json j = bake.toJson();
  j["sampling_errors"] = sampling.toJson()["errors"];
  return j;
}

const ColourErrorRow* ColourErrorReport::find(const std::string& quantity, const std::string& band) const {
  for (const ColourErrorRow& row : rows) {
    if (row.quantity == quantity && row.band == band) return &row;
  }
  return nullptr;
}

nlohmann::ordered_json ColourErrorReport::toJson() const {
  nlohmann::ordered_json j;
  j["reference_wavelengths_nm"] = reference_wavelengths_nm;
  j["reference_paths"] = reference_paths;
  j["compared_lightness"] = kComparedLightness;
  j["white"] = "sRGB (D65)";
  j["smallest_compared_y"] = smallestComparedY(SunBand::Day);
  nlohmann::ordered_json floors;
  for (SunBand band : allSunBands()) floors[sunBandName(band)] = smallestComparedY(band);
  j["smallest_compared_y_by_band"] = floors;
  nlohmann::ordered_json rows_json = nlohmann::ordered_json::array();
  for (const ColourErrorRow& row : rows) {
    const ColourErrorStats& s = row.stats;
    rows_json.push_back({{"quantity", row.quantity},
                         {"band", row.band},
                         {"count", s.count},
                         {"skipped", s.skipped},
                         {"luminance_rms", s.luminance_rms},
                         {"luminance_p95", s.luminance_p95},
                         {"ciede2000_median", s.ciede2000_median},
                         {"ciede2000_p95", s.ciede2000_p95},
                         {"ciede2000_max", s.ciede2000_max},
                         {"reference_luminance_standard_error", s.reference_luminance_standard_error},
                         {"reference_ciede2000_median", s.reference_ciede2000_median},
                         {"reference_ciede2000_p95", s.reference_ciede2000_p95}});
  }
  j["errors"] = rows_json;
  return j;
}

std::string ColourErrorReport::table() const {
  std::string out =
      fmt::format("{:<18} {:<9} {:>5} {:>5}  {:>17}  {:>22}  {:>14}  {:>16}\n", "quantity", "band", "n", "skip",
                  "luminance rms/p95 %", "CIEDE2000 median/p95/max", "ref lum stderr %", "ref CIEDE2000 med/p95");
  for (const ColourErrorRow& row : rows) {
    const ColourErrorStats& s = row.stats;
    out += fmt::format("{:<18} {:<9} {:>5} {:>5}  {:>19}  {:>24}  {:>16.2f}  {:>21}\n", row.quantity, row.band, s.count,
                       s.skipped, fmt::format("{:.2f} / {:.2f}", 100 * s.luminance_rms, 100 * s.luminance_p95),
                       fmt::format("{:.2f} / {:.2f} / {:.2f}", s.ciede2000_median, s.ciede2000_p95, s.ciede2000_max),
                       100 * s.reference_luminance_standard_error,
                       fmt::format("{:.2f} / {:.2f}", s.reference_ciede2000_median, s.reference_ciede2000_p95));
  }
  return out;
}

}  // namespace skybake
