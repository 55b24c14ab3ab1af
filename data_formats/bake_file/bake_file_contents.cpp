#include "data_formats/bake_file/bake_file_contents.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatVectorAttribute.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <fmt/format.h>

#include "data_formats/bake_file/bake_file_attributes.h"
#include "data_formats/config/config.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

using namespace bake_file;

// A density profile's layers as one list of numbers, five per layer (width_m,
// exp_term, exp_scale, linear_term, constant_term), each in the shortest text
// that reads back to the same double.
constexpr size_t kNumbersPerLayer = 5;

// How far the stated mu_s_min may be from cos(sun_max_zenith_deg): skybake
// writes both from the same std::cos of the same double, so they agree
// exactly; another writer's cosine may round a few ulps apart.
constexpr double kStatedCosineTolerance = 1e-12;

std::string numberListText(const std::vector<double>& numbers) {
  std::string text;
  for (double v : numbers) text += fmt::format("{}{}", text.empty() ? "" : " ", v);
  return text;
}

// The numbers of a space-separated list, or false if any token is not one.
bool parseNumberList(std::string_view text, std::vector<double>& numbers) {
  numbers.clear();
  size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ') {
      ++i;
      continue;
    }
    const size_t end = std::min(text.find(' ', i), text.size());
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data() + i, text.data() + end, v);
    if (ec != std::errc() || ptr != text.data() + end) return false;
    numbers.push_back(v);
    i = end;
  }
  return true;
}

std::vector<double> profileNumbers(const DensityProfile& profile) {
  std::vector<double> numbers;
  for (const DensityLayer& l : profile) {
    numbers.insert(numbers.end(), {l.width_m, l.exp_term, l.exp_scale, l.linear_term, l.constant_term});
  }
  return numbers;
}

// groupLaneValues as a float attribute's values.
std::vector<float> groupValues(const std::vector<AtmosphereParameters>& groups,
                               Spectrum AtmosphereParameters::*quantity) {
  const std::vector<double> values = groupLaneValues(groups, quantity);
  return std::vector<float>(values.begin(), values.end());
}

// A per-channel quantity's values in channel order: the atmosphere's lanes,
// or a spectral bake's groups' lanes one after the other.
std::vector<float> spectrumValues(const BakeContents& contents, Spectrum AtmosphereParameters::*quantity) {
  return contents.lane_groups.empty() ? groupValues({contents.atmosphere}, quantity)
                                      : groupValues(contents.lane_groups, quantity);
}

// The per-channel quantities a file states, each one attribute, and (a
// colour bake's) each wavelength's own.
struct SpectrumAttribute {
  const char* name;
  const char* wavelength_name;
  Spectrum AtmosphereParameters::*quantity;
};
constexpr SpectrumAttribute kSpectrumAttributes[] = {
    {kAttrGroundAlbedo, kAttrWavelengthGroundAlbedo, &AtmosphereParameters::ground_albedo},
    {kAttrSunIrradiance, kAttrWavelengthSunIrradiance, &AtmosphereParameters::sun_irradiance},
    {kAttrRayleighScattering, kAttrWavelengthRayleighScattering, &AtmosphereParameters::rayleigh_scattering},
    {kAttrMieScattering, kAttrWavelengthMieScattering, &AtmosphereParameters::mie_scattering},
    {kAttrMieExtinction, kAttrWavelengthMieExtinction, &AtmosphereParameters::mie_extinction},
    {kAttrAbsorptionExtinction, kAttrWavelengthAbsorptionExtinction, &AtmosphereParameters::absorption_extinction},
};

std::string outputsText(const SceneOutputs& outputs) {
  std::string text = "sky_radiance";
  if (outputs.radiance_to_points) text += " radiance_to_points";
  if (outputs.ground_irradiance) text += " ground_irradiance";
  return text;
}

class AttributeReader {
 public:
  AttributeReader(const Imf::Header& header, const std::function<void(const std::string&)>& fail)
      : header_(header), fail_(fail) {}

  template <typename Attribute>
  const auto& value(const char* name) const {
    const Attribute* a = header_.findTypedAttribute<Attribute>(name);
    if (a == nullptr) failWith(fmt::format("attribute {} is missing or of the wrong type", name));
    return a->value();
  }
  double real(const char* name) const { return value<Imf::DoubleAttribute>(name); }
  int integer(const char* name) const { return value<Imf::IntAttribute>(name); }
  bool flag(const char* name) const {
    const int v = integer(name);
    if (v != 0 && v != 1) failWith(fmt::format("attribute {} = {}: must be 0 or 1", name, v));
    return v == 1;
  }
  std::vector<double> numbers(const char* name) const {
    std::vector<double> out;
    if (!parseNumberList(value<Imf::StringAttribute>(name), out)) {
      failWith(fmt::format("attribute {} is not a list of numbers", name));
    }
    return out;
  }
  // Channels first .. first + count - 1 of a per-channel attribute of `channels` values.
  Spectrum spectrum(const char* name, int channels, int first = 0, int count = -1) const {
    const std::vector<float>& values = value<Imf::FloatVectorAttribute>(name);
    if (static_cast<int>(values.size()) != channels) {
      failWith(fmt::format("attribute {} has {} values for {} channels", name, values.size(), channels));
    }
    if (count < 0) count = channels;
    Spectrum s(0.0f);
    for (int c = 0; c < count; ++c) s[c] = values[first + c];
    return s;
  }
  DensityProfile profile(const char* name) const {
    const std::vector<double> n = numbers(name);
    if (n.size() % kNumbersPerLayer != 0) {
      failWith(fmt::format("attribute {} has {} numbers, not {} per layer", name, n.size(), kNumbersPerLayer));
    }
    DensityProfile layers;
    for (size_t i = 0; i < n.size(); i += kNumbersPerLayer)
      layers.push_back({n[i], n[i + 1], n[i + 2], n[i + 3], n[i + 4]});
    return layers;
  }
  Imath::V2i size(const char* name) const { return value<Imf::V2iAttribute>(name); }
  Imath::V2d range(const char* name) const { return value<Imf::V2dAttribute>(name); }
  [[noreturn]] void failWith(const std::string& what) const {
    fail_(what);
    throw Error(ErrorKind::Internal, "the bake-file reader's failure handler returned");
  }

 private:
  const Imf::Header& header_;
  const std::function<void(const std::string&)>& fail_;
};

}  // namespace

void insertContentsAttributes(const BakeContents& contents, Imf::Header& header) {
  const AtmosphereParameters& a = contents.atmosphere;
  header.insert(kAttrWavelengths, Imf::StringAttribute(numberListText(a.wavelengths_nm)));
  // A spectral bake's channels are wavelengths like any other's (FORMAT.md).
  header.insert(kAttrChannels, Imf::StringAttribute(a.storesCieXyz() ? "cie_xyz" : "wavelengths"));
  header.insert(kAttrBottomRadius, Imf::DoubleAttribute(a.bottom_radius_m));
  header.insert(kAttrTopRadius, Imf::DoubleAttribute(a.top_radius_m));
  for (const SpectrumAttribute& attribute : kSpectrumAttributes) {
    header.insert(attribute.name, Imf::FloatVectorAttribute(spectrumValues(contents, attribute.quantity)));
    if (!contents.wavelength_groups.empty()) {
      header.insert(attribute.wavelength_name,
                    Imf::FloatVectorAttribute(groupValues(contents.wavelength_groups, attribute.quantity)));
    }
  }
  header.insert(kAttrSunAngularRadius, Imf::DoubleAttribute(a.sun_angular_radius_rad));
  header.insert(kAttrSunMaxZenith, Imf::DoubleAttribute(a.sun_max_zenith_deg));
  header.insert(kAttrRayleighDensity, Imf::StringAttribute(numberListText(profileNumbers(a.rayleigh_density))));
  header.insert(kAttrMiePhaseG, Imf::DoubleAttribute(a.mie_phase_g));
  header.insert(kAttrMieDensity, Imf::StringAttribute(numberListText(profileNumbers(a.mie_density))));
  header.insert(kAttrAbsorptionDensity, Imf::StringAttribute(numberListText(profileNumbers(a.absorption_density))));

  const TextureSizes& s = contents.sizes;
  header.insert(kAttrOpticalDepthSize, Imf::V2iAttribute({s.transmittance_mu, s.transmittance_r}));
  header.insert(kAttrIrradianceSize, Imf::V2iAttribute({s.irradiance_mu_s, s.irradiance_r}));
  header.insert(kAttrScatteringSizeRMu, Imf::V2iAttribute({s.scattering_r, s.scattering_mu}));
  header.insert(kAttrScatteringSizeMuSNu, Imf::V2iAttribute({s.scattering_mu_s, s.scattering_nu}));
  header.insert(kAttrDensityViewSize, Imf::IntAttribute(contents.density_view_size));
  header.insert(kAttrOutputs, Imf::StringAttribute(outputsText(contents.outputs)));
  header.insert(kAttrCombinedSingleMie, Imf::IntAttribute(contents.combined_single_mie ? 1 : 0));
  header.insert(kAttrStoredFractionBits, Imf::IntAttribute(contents.stored_fraction_bits));

  const AtmosphereDomain& d = contents.domain;
  const ScatteringSizes ss = ScatteringSizes::fromTextureSizes(s);
  header.insert(kAttrMuSMin, Imf::DoubleAttribute(d.mu_s_min));
  header.insert(kAttrScatteringRRange,
                Imf::V2dAttribute({rFromScatteringTexel(d, ss, 0), rFromScatteringTexel(d, ss, ss.r - 1)}));
  header.insert(kAttrScatteringMuSRange,
                Imf::V2dAttribute({muSFromScatteringTexel(d, ss, 0), muSFromScatteringTexel(d, ss, ss.mu_s - 1)}));
  header.insert(kAttrScatteringRhoRange, Imf::V2dAttribute({d.scattering_rho_min_m, d.scattering_rho_max_m}));
  header.insert(kAttrScatteringMuSCoordRange,
                Imf::V2dAttribute({d.scattering_mu_s_coord_min, d.scattering_mu_s_coord_max}));
  header.insert(kAttrScatteringGroundViews, Imf::IntAttribute(d.scattering_ground_views ? 1 : 0));
}

BakeContents readContentsAttributes(const Imf::Header& header, int format_version,
                                    const std::function<void(const std::string&)>& fail) {
  const AttributeReader in(header, fail);
  BakeContents c;
  AtmosphereParameters& a = c.atmosphere;
  a.wavelengths_nm = in.numbers(kAttrWavelengths);
  if (format_version >= 4) {
    const std::string& kind = in.value<Imf::StringAttribute>(kAttrChannels);
    if (kind == "cie_xyz") {
      a.channel_kind = ChannelKind::CieXyz;
    } else if (kind != "wavelengths") {
      in.failWith(fmt::format("attribute {} = \"{}\": must be \"wavelengths\" or \"cie_xyz\"", kAttrChannels, kind));
    }
  }
  const int wavelengths = static_cast<int>(a.wavelengths_nm.size());
  // Wavelength channels beyond one Spectrum's lanes are a spectral bake's.
  const int max_wavelengths = a.storesCieXyz() ? kMaxColourWavelengths : kMaxSpectralWavelengths;
  if (wavelengths < 1 || wavelengths > max_wavelengths) {
    in.failWith(fmt::format("attribute {} lists {} wavelengths; a {} bake has 1 to {}", kAttrWavelengths, wavelengths,
                            a.storesCieXyz() ? "colour" : "wavelength", max_wavelengths));
  }
  if (!a.storesCieXyz() && wavelengths > kMaxChannels) a.channel_kind = ChannelKind::Spectral;
  const int n = a.channelCount();
  a.bottom_radius_m = in.real(kAttrBottomRadius);
  a.top_radius_m = in.real(kAttrTopRadius);
  a.sun_angular_radius_rad = in.real(kAttrSunAngularRadius);
  a.sun_max_zenith_deg = in.real(kAttrSunMaxZenith);
  a.rayleigh_density = in.profile(kAttrRayleighDensity);
  a.mie_phase_g = in.real(kAttrMiePhaseG);
  a.mie_density = in.profile(kAttrMieDensity);
  a.absorption_density = in.profile(kAttrAbsorptionDensity);
  // `a`'s wavelengths in groups of at most kMaxChannels, each an ordinary
  // atmosphere of those wavelengths with its values of every per-channel
  // quantity from the attributes named by `name`.
  const int wavelength_count = static_cast<int>(a.wavelengths_nm.size());
  auto wavelengthGroups = [&](const char* const SpectrumAttribute::*name) {
    std::vector<AtmosphereParameters> groups;
    for (int first = 0; first < wavelength_count; first += kMaxChannels) {
      const int count = std::min(kMaxChannels, wavelength_count - first);
      AtmosphereParameters g = a;
      g.channel_kind = ChannelKind::Wavelengths;
      g.wavelengths_nm.assign(a.wavelengths_nm.begin() + first, a.wavelengths_nm.begin() + first + count);
      for (const SpectrumAttribute& attribute : kSpectrumAttributes) {
        g.*attribute.quantity = in.spectrum(attribute.*name, wavelength_count, first, count);
      }
      groups.push_back(std::move(g));
    }
    return groups;
  };
  if (a.storesLaneGroups()) {
    c.lane_groups = wavelengthGroups(&SpectrumAttribute::name);
  } else {
    for (const SpectrumAttribute& attribute : kSpectrumAttributes)
      a.*attribute.quantity = in.spectrum(attribute.name, n);
  }
  if (a.storesCieXyz() && format_version >= kFirstWavelengthDepthFormatVersion) {
    c.wavelength_groups = wavelengthGroups(&SpectrumAttribute::wavelength_name);
  }

  TextureSizes& s = c.sizes;
  const Imath::V2i optical_depth = in.size(kAttrOpticalDepthSize);
  const Imath::V2i irradiance = in.size(kAttrIrradianceSize);
  const Imath::V2i r_mu = in.size(kAttrScatteringSizeRMu);
  const Imath::V2i mu_s_nu = in.size(kAttrScatteringSizeMuSNu);
  s = {optical_depth.x, optical_depth.y, irradiance.x, irradiance.y, r_mu.x,
       r_mu.y,          mu_s_nu.x,       mu_s_nu.y,    std::nullopt, std::nullopt};
  // Stated since version 7 (and by a file of that writer on Bruneton's sun
  // axis, written at version 4); before, the density had the others' size.
  const bool states_density_size = header.findTypedAttribute<Imf::IntAttribute>(kAttrDensityViewSize) != nullptr;
  c.density_view_size = states_density_size || format_version >= kFirstDensityViewSizeFormatVersion
                            ? in.integer(kAttrDensityViewSize)
                            : s.scattering_mu;

  c.outputs.radiance_to_points = false;
  c.outputs.ground_irradiance = false;
  bool sky_radiance = false;
  const std::string& outputs = in.value<Imf::StringAttribute>(kAttrOutputs);
  for (size_t i = 0; i < outputs.size();) {
    const size_t end = std::min(outputs.find(' ', i), outputs.size());
    const std::string_view name(outputs.data() + i, end - i);
    if (name == "sky_radiance") {
      sky_radiance = true;
    } else if (name == "radiance_to_points") {
      c.outputs.radiance_to_points = true;
    } else if (name == "ground_irradiance") {
      c.outputs.ground_irradiance = true;
    } else if (!name.empty()) {
      in.failWith(fmt::format("attribute {} names an unknown output", kAttrOutputs));
    }
    i = end + 1;
  }
  if (!sky_radiance) in.failWith(fmt::format("attribute {} lacks sky_radiance, which every bake holds", kAttrOutputs));
  c.combined_single_mie = in.flag(kAttrCombinedSingleMie);
  // Files written before the attribute kept every bit.
  c.stored_fraction_bits = header.findTypedAttribute<Imf::IntAttribute>(kAttrStoredFractionBits) != nullptr
                               ? in.integer(kAttrStoredFractionBits)
                               : kFloatFractionBits;

  AtmosphereDomain& d = c.domain;
  d = AtmosphereDomain::fromParameters(a);
  d.sun_axis = sunAxisOfFormatVersion(format_version);
  d.irradiance_rows = irradianceRowsOfFormatVersion(format_version);
  const Imath::V2d rho = in.range(kAttrScatteringRhoRange);
  const Imath::V2d mu_s_coord = in.range(kAttrScatteringMuSCoordRange);
  d.scattering_rho_min_m = rho.x;
  d.scattering_rho_max_m = rho.y;
  d.scattering_mu_s_coord_min = mu_s_coord.x;
  d.scattering_mu_s_coord_max = mu_s_coord.y;
  d.scattering_ground_views = in.flag(kAttrScatteringGroundViews);
  // The lowest sun is stated twice, as an angle (the atmosphere's) and as the
  // cosine the sun coordinate starts at; a file where they disagree is forged.
  const double mu_s_min = in.real(kAttrMuSMin);
  if (!(std::abs(mu_s_min - d.mu_s_min) <= kStatedCosineTolerance)) {
    in.failWith(fmt::format("attribute {} = {} disagrees with {} = {} (cosine {})", kAttrMuSMin, mu_s_min,
                            kAttrSunMaxZenith, a.sun_max_zenith_deg, d.mu_s_min));
  }
  return c;
}

void validateContents(const BakeContents& contents, const std::string& source) {
  BakeConfig config;
  config.atmosphere = contents.atmosphere;
  config.sizes = contents.sizes;
  config.scene = contents.outputs;
  config.bake.precision = contents.precision;
  config.bake.stored_fraction_bits = contents.stored_fraction_bits;
  config.bake.combined_single_mie = contents.combined_single_mie;
  config.scene_ranges.views_below_horizon = contents.domain.scattering_ground_views;
  // Each wavelength group is checked as its own pass's atmosphere.
  config.colour_groups = contents.lane_groups.empty() ? contents.wavelength_groups : contents.lane_groups;
  validateConfig(config, source);
  // The density's view axis is linear over [-1, 1] with a texel at each end
  // (muFromDensityTexel), so it needs 2; more than the radiance tables' view
  // texels no writer makes.
  if (!(contents.density_view_size >= 2 && contents.density_view_size <= contents.sizes.scattering_mu)) {
    throwBadInput(fmt::format("{}: {} = {}: must be in [2, {}] (the 4D tables' view texels)", source,
                              kAttrDensityViewSize, contents.density_view_size, contents.sizes.scattering_mu));
  }
  if (contents.combined_single_mie && !bakeStoresSingleMie(contents)) {
    throwBadInput(fmt::format("{}: {} = 1 but no channel has Mie scattering", source, kAttrCombinedSingleMie));
  }
  const AtmosphereDomain& d = contents.domain;
  const double H = d.horizonToTopDistance();
  if (!(d.scattering_rho_min_m >= 0.0 && d.scattering_rho_min_m <= d.scattering_rho_max_m &&
        d.scattering_rho_max_m <= H)) {
    throwBadInput(fmt::format("{}: {} = ({}, {}): must be ordered ends within [0, {}] (the atmosphere's)", source,
                              kAttrScatteringRhoRange, d.scattering_rho_min_m, d.scattering_rho_max_m, H));
  }
  if (!(d.scattering_mu_s_coord_min >= 0.0 && d.scattering_mu_s_coord_min <= d.scattering_mu_s_coord_max &&
        d.scattering_mu_s_coord_max <= 1.0)) {
    throwBadInput(fmt::format("{}: {} = ({}, {}): must be ordered ends within [0, 1]", source,
                              kAttrScatteringMuSCoordRange, d.scattering_mu_s_coord_min, d.scattering_mu_s_coord_max));
  }
}

}  // namespace skybake
