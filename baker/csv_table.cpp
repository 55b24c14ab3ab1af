#include "baker/csv_table.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <fmt/format.h>

#include "data_formats/atomic_file.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

std::vector<std::string> splitCells(const std::string& line) {
  std::vector<std::string> cells;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    std::string cell = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const size_t first = cell.find_first_not_of(" \t\r");
    const size_t last = cell.find_last_not_of(" \t\r");
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& path) {
  CsvTable table;
  table.path_ = path.string();
  std::ifstream in(path);
  if (!in) throwBadInput(fmt::format("{}: cannot open query file", table.path_));
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    std::vector<std::string> cells = splitCells(line);
    if (table.columns_.empty()) {
      table.columns_ = cells;
      continue;
    }
    if (cells.size() != table.columns_.size()) {
      throwBadInput(fmt::format("{}:{}: {} cells, the header has {} columns", table.path_, line_number,
                                cells.size(), table.columns_.size()));
    }
    std::vector<double> values;
    for (size_t c = 0; c < cells.size(); ++c) {
      double v = 0.0;
      const char* begin = cells[c].data();
      const char* end = begin + cells[c].size();
      const auto [ptr, ec] = std::from_chars(begin, end, v);
      if (cells[c].empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) {
        throwBadInput(fmt::format("{}:{}:{} ({}): '{}' is not a finite number", table.path_, line_number,
                                  c + 1, table.columns_[c], cells[c]));
      }
      values.push_back(v);
    }
    table.rows_.push_back(std::move(values));
    table.texts_.push_back(std::move(cells));
    table.line_numbers_.push_back(line_number);
  }
  if (table.columns_.empty()) throwBadInput(fmt::format("{}: no header row", table.path_));
  return table;
}

std::optional<size_t> CsvTable::find(const std::string& name) const {
  for (size_t i = 0; i < columns_.size(); ++i) {
    if (columns_[i] == name) return i;
  }
  return std::nullopt;
}

size_t CsvTable::require(const std::string& name) const {
  if (auto i = find(name)) return *i;
  throwBadInput(fmt::format("{}:1: missing column '{}'", path_, name));
}

void CsvTable::requireRange(size_t column, double lo, double hi) const {
  for (size_t row = 0; row < rows_.size(); ++row) {
    const double v = rows_[row][column];
    if (v < lo || v > hi) {
      throwBadInput(fmt::format("{}:{}:{} ({}): {} is out of range [{}, {}]", path_, line_numbers_[row],
                                column + 1, columns_[column], texts_[row][column], lo, hi));
    }
  }
}

void writeCsvOutput(const std::string& path, const std::string& text) {
  if (path.empty()) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    return;
  }
  writeFileAtomically(path, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throwBadInput(fmt::format("{}: cannot write", path));
  });
}

}  // namespace skybake
