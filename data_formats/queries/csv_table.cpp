#include "data_formats/queries/csv_table.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string_view>

#include <fmt/format.h>

#include "data_formats/atomic_file.h"
#include "data_formats/error.h"
#include "data_formats/text_numbers.h"

namespace skybake {
namespace {

// No query line comes near this (a row of numbers is tens of bytes); a longer
// one means the file is not a query CSV (binary data, a file without line
// breaks) and would otherwise be read whole into memory.
constexpr size_t kMaxLineBytes = 65536;

// Splits one line into cells (RFC 4180 on a single line): a cell may be
// quoted, so that R's write.csv headers ("altitude_m") and quoted numbers
// read as their text; inside quotes a doubled quote is one quote and commas
// and spaces belong to the cell. Unquoted cells are trimmed of blanks (and
// of the '\r' of a CRLF line end). A quoted cell that does not end on its
// line, or has text after its closing quote, throws Error(BadInput) with its
// line and column: a query file has no multi-line cells, so this is a broken
// file, and guessing would misalign every later column.
std::vector<std::string> splitCells(std::string_view line, const std::string& path, int line_number) {
  std::vector<std::string> cells;
  size_t pos = 0;
  while (true) {
    const size_t start = line.find_first_not_of(" \t", pos);
    if (start != std::string_view::npos && line[start] == '"') {
      std::string cell;
      size_t i = start + 1;
      while (true) {
        const size_t quote = line.find('"', i);
        if (quote == std::string_view::npos) {
          throwBadInput(fmt::format("{}:{}:{}: quoted cell has no closing quote on its line", path, line_number,
                                    cells.size() + 1));
        }
        cell.append(line.substr(i, quote - i));
        if (quote + 1 < line.size() && line[quote + 1] == '"') {
          cell += '"';
          i = quote + 2;
          continue;
        }
        i = quote + 1;
        break;
      }
      const size_t after = line.find_first_not_of(kCellBlanks, i);
      if (after != std::string_view::npos && line[after] != ',') {
        throwBadInput(fmt::format("{}:{}:{}: text after the closing quote of a quoted cell", path, line_number,
                                  cells.size() + 1));
      }
      cells.push_back(std::move(cell));
      if (after == std::string_view::npos) break;
      pos = after + 1;
      continue;
    }
    const size_t comma = line.find(',', pos);
    cells.emplace_back(
        trimmedCell(line.substr(pos, comma == std::string_view::npos ? std::string_view::npos : comma - pos)));
    if (comma == std::string_view::npos) break;
    pos = comma + 1;
  }
  return cells;
}

bool isBlank(const std::string& text) { return text.find_first_not_of(kCellBlanks) == std::string::npos; }

bool isCommentLine(const std::string& line) { return !line.empty() && line[0] == '#'; }

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
  // The last '#' line before the first other line: numpy.savetxt writes its
  // header as "# name,name,...", so when no header follows it is the header.
  std::string last_comment;
  int last_comment_line = 0;
  while (readLine(in_, line_, path_, line_number_ + 1)) {
    ++line_number_;
    if (line_number_ == 1 && line_.starts_with(kUtf8ByteOrderMark)) line_.erase(0, kUtf8ByteOrderMark.size());
    if (isBlank(line_)) continue;
    if (isCommentLine(line_)) {
      last_comment = line_.substr(1);
      last_comment_line = line_number_;
      continue;
    }
    std::vector<std::string> names = splitCells(line_, path_, line_number_);
    header_line_ = line_number_;
    if (last_comment_line != 0 && !isBlank(last_comment)) {
      double unused = 0.0;
      bool all_numbers = true;
      for (const std::string& cell : names) all_numbers = all_numbers && parseFiniteNumber(cell, unused);
      if (all_numbers) {
        // This line is the first data row; read it again in next().
        pending_row_ = true;
        names = splitCells(last_comment, path_, last_comment_line);
        header_line_ = last_comment_line;
      }
    }
    // R's write.csv puts the row names first, under an empty name: that
    // column is left out (it may hold any text, and is not a query's).
    if (names.size() > 1 && names[0].empty()) {
      skipped_columns_ = 1;
      names.erase(names.begin());
    }
    for (size_t c = 0; c < names.size(); ++c) {
      if (names[c].empty()) {
        throwBadInput(
            fmt::format("{}:{}:{}: empty column name in the header", path_, header_line_, c + 1 + skipped_columns_));
      }
      for (size_t earlier = 0; earlier < c; ++earlier) {
        if (names[earlier] == names[c]) {
          throwBadInput(fmt::format("{}:{}:{}: column '{}' appears twice (also column {})", path_, header_line_,
                                    c + 1 + skipped_columns_, names[c], earlier + 1 + skipped_columns_));
        }
      }
    }
    columns_ = std::move(names);
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
  while (pending_row_ || readLine(in_, line_, path_, line_number_ + 1)) {
    if (pending_row_) {
      pending_row_ = false;
    } else {
      ++line_number_;
    }
    if (isBlank(line_) || isCommentLine(line_)) continue;
    std::vector<std::string> cells = splitCells(line_, path_, line_number_);
    const size_t file_columns = columns_.size() + skipped_columns_;
    if (cells.size() != file_columns) {
      throwBadInput(fmt::format("{}:{}:{}: {} cells, the header (line {}) has {} columns", path_, line_number_,
                                std::min(cells.size(), file_columns) + 1, cells.size(), header_line_, file_columns));
    }
    cells.erase(cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(skipped_columns_));
    row.values.resize(cells.size());
    for (size_t c = 0; c < cells.size(); ++c) {
      if (c < value_when_empty_.size() && value_when_empty_[c] && isBlank(cells[c])) {
        row.values[c] = *value_when_empty_[c];
      } else if (!parseFiniteNumber(cells[c], row.values[c])) {
        throwBadInput(fmt::format("{}:{}:{} ({}): '{}' is not a finite number", path_, line_number_,
                                  c + 1 + skipped_columns_, columns_[c], cells[c]));
      }
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

std::optional<size_t> CsvReader::findOptional(const std::string& name, double value_when_empty) {
  const std::optional<size_t> column = find(name);
  if (column) {
    value_when_empty_.resize(columns_.size());
    value_when_empty_[*column] = value_when_empty;
  }
  return column;
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
  throwBadInput(fmt::format("{}:{}:{} ({}): {} {}", path_, row.line_number, column + 1 + skipped_columns_,
                            columns_[column], row.texts[column], reason));
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
