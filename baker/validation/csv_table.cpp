#include "baker/validation/csv_table.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string_view>

#include <fmt/format.h>

#include "data_formats/atomic_file.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

// No query line comes near this (a row of numbers is tens of bytes); a longer
// one means the file is not a query CSV (binary data, a file without line
// breaks) and would otherwise be read whole into memory.
constexpr size_t kMaxLineBytes = 65536;

// The byte-order mark some spreadsheets put before the header.
constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

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

// Reads one line of at most kMaxLineBytes into `line`; false at the end of
// the input. Throws Error(BadInput) for a longer line.
bool readLine(std::istream& in, std::string& line, const std::string& path, int line_number) {
  line.resize(kMaxLineBytes + 1);
  in.getline(line.data(), static_cast<std::streamsize>(line.size()));
  const std::streamsize read = in.gcount();
  if (in.fail() && !in.eof() && read == static_cast<std::streamsize>(kMaxLineBytes)) {
    throwBadInput(fmt::format("{}:{}: line longer than {} bytes: not a query CSV", path, line_number, kMaxLineBytes));
  }
  if (read == 0 && (in.eof() || in.fail())) return false;
  // gcount counts the newline getline consumed but did not store.
  line.resize(static_cast<size_t>(read) - (in.eof() ? 0 : 1));
  return true;
}

}  // namespace

CsvReader::CsvReader(const std::filesystem::path& path) : path_(path.string()) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throwBadInput(fmt::format("{}: is a directory, not a query file", path_));
  }
  in_.open(path, std::ios::binary);
  if (!in_) throwBadInput(fmt::format("{}: cannot open query file: {}", path_, std::strerror(errno)));
  while (readLine(in_, line_, path_, line_number_ + 1)) {
    ++line_number_;
    if (line_number_ == 1 && line_.starts_with(kUtf8ByteOrderMark)) line_.erase(0, kUtf8ByteOrderMark.size());
    if (line_.find_first_not_of(" \t\r") == std::string::npos || line_[0] == '#') continue;
    std::vector<std::string> names = splitCells(line_);
    for (size_t c = 0; c < names.size(); ++c) {
      if (names[c].empty()) {
        throwBadInput(fmt::format("{}:{}:{}: empty column name in the header", path_, line_number_, c + 1));
      }
      for (size_t earlier = 0; earlier < c; ++earlier) {
        if (names[earlier] == names[c]) {
          throwBadInput(fmt::format("{}:{}:{}: column '{}' appears twice (also column {})", path_, line_number_, c + 1,
                                    names[c], earlier + 1));
        }
      }
    }
    columns_ = std::move(names);
    header_line_ = line_number_;
    return;
  }
  if (in_.bad()) throwBadInput(fmt::format("{}:{}: read error", path_, line_number_ + 1));
  throwBadInput(fmt::format("{}: no header row: the file is empty", path_));
}

bool CsvReader::next(CsvRow& row) {
  if (readRow(row)) {
    ++rows_read_;
    return true;
  }
  if (in_.bad()) throwBadInput(fmt::format("{}:{}: read error", path_, line_number_ + 1));
  if (rows_read_ == 0) throwBadInput(fmt::format("{}: no query rows after the header (line {})", path_, header_line_));
  return false;
}

bool CsvReader::readRow(CsvRow& row) {
  while (readLine(in_, line_, path_, line_number_ + 1)) {
    ++line_number_;
    if (line_.find_first_not_of(" \t\r") == std::string::npos || line_[0] == '#') continue;
    std::vector<std::string> cells = splitCells(line_);
    if (cells.size() != columns_.size()) {
      throwBadInput(fmt::format("{}:{}:{}: {} cells, the header (line {}) has {} columns", path_, line_number_,
                                std::min(cells.size(), columns_.size()) + 1, cells.size(), header_line_,
                                columns_.size()));
    }
    row.values.resize(cells.size());
    for (size_t c = 0; c < cells.size(); ++c) {
      double v = 0.0;
      const char* begin = cells[c].data();
      const char* end = begin + cells[c].size();
      const auto [ptr, ec] = std::from_chars(begin, end, v);
      if (cells[c].empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) {
        throwBadInput(fmt::format("{}:{}:{} ({}): '{}' is not a finite number", path_, line_number_, c + 1, columns_[c],
                                  cells[c]));
      }
      row.values[c] = v;
    }
    row.texts = std::move(cells);
    row.line_number = line_number_;
    return true;
  }
  return false;
}

std::optional<size_t> CsvReader::find(const std::string& name) const {
  for (size_t i = 0; i < columns_.size(); ++i) {
    if (columns_[i] == name) return i;
  }
  return std::nullopt;
}

size_t CsvReader::require(const std::string& name) const {
  if (auto i = find(name)) return *i;
  std::string present;
  for (const std::string& c : columns_) present += (present.empty() ? "" : ", ") + c;
  throwBadInput(fmt::format("{}:{}: missing column '{}' (the header has: {})", path_, header_line_, name, present));
}

void CsvReader::requireRange(const CsvRow& row, size_t column, double lo, double hi) const {
  const double v = row.values[column];
  if (v < lo || v > hi) failCell(row, column, fmt::format("is out of range [{:g}, {:g}]", lo, hi));
}

void CsvReader::failCell(const CsvRow& row, size_t column, const std::string& reason) const {
  throwBadInput(fmt::format("{}:{}:{} ({}): {} {}", path_, row.line_number, column + 1, columns_[column],
                            row.texts[column], reason));
}

void writeCsvOutput(const std::string& path,
                    const std::function<void(const std::function<void(std::string_view)>& emit)>& produce) {
  if (path.empty()) {
    produce([](std::string_view piece) { std::fwrite(piece.data(), 1, piece.size(), stdout); });
    return;
  }
  writeFileStreamAtomically(path, produce);
}

}  // namespace skybake
