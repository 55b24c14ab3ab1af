// Numeric CSV query files for `skybake lookup` and `--queries`: a header row
// of column names, then rows of numbers, read one row at a time so that
// memory does not grow with the file. Errors name the file, line and column.
// What common tools write is read as is: cells may be quoted (RFC 4180 on
// one line: "" is a quote, commas inside quotes belong to the cell), lines
// may end in CRLF, a header may be numpy.savetxt's "# a,b,..." line, and R's
// write.csv leading row-name column (empty name) is left out.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skybake {

// One row: its numbers, their original text (written back unchanged in
// outputs) and its line in the file.
struct CsvRow {
  std::vector<double> values;
  std::vector<std::string> texts;
  int line_number = 0;
};

class CsvReader {
 public:
  // Opens `path` and reads its header: distinct, non-empty names ('#' lines
  // and blank lines are skipped throughout, except that when the first other
  // line is all numbers the last '#' line before it, less its '#', is the
  // header: numpy.savetxt's). A first column with an empty name, when there
  // are others, is left out of columns() and rows; error columns still count
  // it, as they are the file's. Throws Error(BadInput)
  // "<path>:<line>:<column>: <reason>" for a bad header, "<path>: <reason>"
  // for a missing file or one with no header.
  explicit CsvReader(const std::filesystem::path& path);

  const std::vector<std::string>& columns() const { return columns_; }
  // Index of a column, or nullopt.
  std::optional<size_t> find(const std::string& name) const;
  // Index of an optional column, or nullopt; in the rows read after this an
  // empty cell of it (nothing but spaces between its commas) reads as
  // `value_when_empty`, what leaving the column out means, and any other
  // cell must still be a finite number.
  std::optional<size_t> findOptional(const std::string& name, double value_when_empty);
  // Index of a required column; throws Error(BadInput) naming the file.
  size_t require(const std::string& name) const;

  // The next row, one finite number per column, or false at the end of the
  // file. Throws Error(BadInput) "<path>:<line>:<column> (<name>): <reason>"
  // for the first bad cell, "<path>:<line>: <reason>" for a bad line and
  // "<path>: no query rows ..." at the end of a file that had none.
  bool next(CsvRow& row);

  // Throws Error(BadInput) for a cell of `row` outside [lo, hi], with its position.
  void requireRange(const CsvRow& row, size_t column, double lo, double hi) const;
  // Throws Error(BadInput) "<path>:<line>:<column> (<name>): <text> <reason>".
  [[noreturn]] void failCell(const CsvRow& row, size_t column, const std::string& reason) const;

 private:
  bool readRow(CsvRow& row);

  std::string path_;
  std::ifstream in_;
  std::string line_;
  int line_number_ = 0;
  int header_line_ = 0;
  // Set when line_ holds the first data row, already read while looking for
  // a numpy.savetxt header.
  bool pending_row_ = false;
  // Leading columns of the file left out of columns() and rows: 1 for the
  // unnamed row-name column of R's write.csv, else 0.
  size_t skipped_columns_ = 0;
  size_t rows_read_ = 0;
  std::vector<std::string> columns_;
  // Per column: what an empty cell reads as, for the optional ones.
  std::vector<std::optional<double>> value_when_empty_;
};

// Writes CSV text produced piece by piece to `path` atomically
// (writeFileStreamAtomically), or to stdout when path is empty.
void writeCsvOutput(const std::string& path,
                    const std::function<void(const std::function<void(std::string_view)>& emit)>& produce);

}  // namespace skybake
