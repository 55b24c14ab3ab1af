#include "data_formats/spectra/spectrum_csv.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "data_formats/error.h"
#include "data_formats/input_file.h"
#include "data_formats/terminal_text.h"
#include "data_formats/text_numbers.h"

namespace skybake {
namespace {

// A measured spectrum at 0.01 nm over 200 to 1100 nm is 90 000 lines, about
// 2 MiB. A file far beyond that is not a spectrum (a device, a log, binary
// data) and would otherwise be read whole into memory.
constexpr std::uintmax_t kMaxSpectrumFileBytes = 64u << 20;

// The tables hold floats: a value beyond this would become infinite in them,
// reported against the config key with the file no longer named.
constexpr double kMaxSpectrumValue = std::numeric_limits<float>::max();

// Linear interpolation needs a sample on each side of a wavelength.
constexpr size_t kMinSpectrumSamples = 2;

bool isBlank(std::string_view line) { return line.find_first_not_of(kCellBlanks) == std::string_view::npos; }

}  // namespace

TabulatedSpectrum readSpectrumCsv(const std::filesystem::path& path) {
  const std::string name = path.string();
  requireInputFile(path, "spectrum file", kMaxSpectrumFileBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throwBadInput(fmt::format("{}: cannot open spectrum file", name));

  TabulatedSpectrum spectrum;
  std::string line;
  int line_number = 0;
  bool header_allowed = true;
  int previous_line = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line_number == 1 && line.starts_with(kUtf8ByteOrderMark)) line.erase(0, kUtf8ByteOrderMark.size());
    if (isBlank(line) || line[0] == '#') continue;
    const size_t comma = line.find(',');
    const std::string whole = shownText(trimmedCell(line));
    if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos) {
      throwBadInput(fmt::format("{}:{}: {}: needs two columns, wavelength_nm,value", name, line_number, whole));
    }
    const std::string_view wavelength_cell = trimmedCell(std::string_view(line).substr(0, comma));
    const std::string_view value_cell = trimmedCell(std::string_view(line).substr(comma + 1));
    double wavelength_nm = 0.0;
    double value = 0.0;
    const bool wavelength_ok = parseFiniteNumber(wavelength_cell, wavelength_nm);
    const bool value_ok = parseFiniteNumber(value_cell, value);
    // The cells as messages quote them: escaped, a long one shortened.
    const std::string wavelength_text = shownText(wavelength_cell);
    const std::string value_text = shownText(value_cell);
    if (header_allowed && !wavelength_ok && !value_ok) {  // column names
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (!wavelength_ok) {
      throwBadInput(
          fmt::format("{}:{}: wavelength {}: must be a finite number (nm)", name, line_number, wavelength_text));
    }
    if (!value_ok)
      throwBadInput(fmt::format("{}:{}: value {}: must be a finite number", name, line_number, value_text));
    if (!(std::abs(value) <= kMaxSpectrumValue)) {
      throwBadInput(fmt::format("{}:{}: value {}: beyond the {:g} a table's float holds", name, line_number, value_text,
                                kMaxSpectrumValue));
    }
    if (!(wavelength_nm > 0.0)) {
      throwBadInput(fmt::format("{}:{}: wavelength {} nm: must be > 0", name, line_number, wavelength_text));
    }
    if (!spectrum.wavelengths_nm.empty() && !(wavelength_nm > spectrum.wavelengths_nm.back())) {
      throwBadInput(fmt::format("{}:{}: wavelength {} nm: {} line {}'s {} nm: wavelengths must increase down the file",
                                name, line_number, wavelength_text,
                                wavelength_nm == spectrum.wavelengths_nm.back() ? "repeats" : "is below", previous_line,
                                spectrum.wavelengths_nm.back()));
    }
    spectrum.wavelengths_nm.push_back(wavelength_nm);
    spectrum.values.push_back(value);
    previous_line = line_number;
  }
  if (spectrum.wavelengths_nm.size() < kMinSpectrumSamples) {
    throwBadInput(fmt::format("{}: {} samples: a spectrum needs at least {} (wavelength_nm,value lines)", name,
                              spectrum.wavelengths_nm.size(), kMinSpectrumSamples));
  }
  return spectrum;
}

}  // namespace skybake
