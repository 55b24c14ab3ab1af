// Numeric CSV tables for `skybake lookup`: a header row of column names, then
// rows of numbers. Errors name the file, line and column.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace skybake {

class CsvTable {
 public:
  // Reads `path`: a header of distinct, non-empty names, then at least one
  // row with one finite number per column ('#' lines and blank lines are
  // skipped). Throws Error(BadInput) "<path>:<line>:<column> (<name>):
  // <reason>" for the first bad cell, "<path>:<line>: <reason>" for a bad
  // line and "<path>: <reason>" for a file with no header or no rows.
  static CsvTable read(const std::filesystem::path& path);

  const std::vector<std::string>& columns() const { return columns_; }
  size_t rowCount() const { return rows_.size(); }
  // Index of a column, or nullopt.
  std::optional<size_t> find(const std::string& name) const;
  // Index of a required column; throws Error(BadInput) naming the file.
  size_t require(const std::string& name) const;
  double value(size_t row, size_t column) const { return rows_[row][column]; }
  // The original text of a cell (written back unchanged in outputs).
  const std::string& text(size_t row, size_t column) const { return texts_[row][column]; }
  // Throws Error(BadInput) for a cell outside [lo, hi], with its position.
  void requireRange(size_t column, double lo, double hi) const;
  // Throws Error(BadInput) "<path>:<line>:<column> (<name>): <text> <reason>".
  [[noreturn]] void failCell(size_t row, size_t column, const std::string& reason) const;

 private:
  void checkHeader(const std::vector<std::string>& names, int line_number) const;

  std::string path_;
  int header_line_ = 0;
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
  std::vector<std::vector<std::string>> texts_;
  std::vector<int> line_numbers_;
};

// Writes CSV text to `path` atomically, or to stdout when path is empty.
void writeCsvOutput(const std::string& path, const std::string& text);

}  // namespace skybake
