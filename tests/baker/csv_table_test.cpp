// Query CSVs as common tools write them (R's write.csv, numpy.savetxt,
// spreadsheets with CRLF) read to the same columns and numbers as a plain
// file, and broken quoting is reported with its line and column instead of
// shifting every later cell.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "data_formats/error.h"
#include "data_formats/queries/csv_table.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

class CsvReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("csv_reader_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& text) {
    const fs::path p = dir_ / "q.csv";
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

  // Every row of the file, read to the end.
  static std::vector<CsvRow> readAll(CsvReader& reader) {
    std::vector<CsvRow> rows;
    CsvRow row;
    while (reader.next(row)) rows.push_back(row);
    return rows;
  }

  void expectBadInput(const std::string& text, const std::string& fragment) {
    const fs::path p = write(text);
    try {
      CsvReader reader(p);
      readAll(reader);
      FAIL() << "accepted: " << text;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadInput);
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }

  fs::path dir_;
};

const std::vector<std::string> kRadianceColumns = {"altitude_m", "sun_zenith_deg", "view_zenith_deg",
                                                   "view_azimuth_deg"};

TEST_F(CsvReaderTest, PlainFileReadsNamesNumbersAndLines) {
  CsvReader reader(write("altitude_m, sun_zenith_deg\n# a comment\n0,30\n\n1000 , 60.5\n"));
  EXPECT_EQ(reader.columns(), (std::vector<std::string>{"altitude_m", "sun_zenith_deg"}));
  const std::vector<CsvRow> rows = readAll(reader);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].values, (std::vector<double>{1000.0, 60.5}));
  EXPECT_EQ(rows[1].texts, (std::vector<std::string>{"1000", "60.5"}));
  EXPECT_EQ(rows[1].line_number, 5);
}

// Exactly what R's write.csv(data.frame(...)) writes: quoted names, a first
// unnamed column of quoted row names, CRLF on Windows.
TEST_F(CsvReaderTest, RWriteCsvWithRowNamesAndCrlf) {
  CsvReader reader(
      write("\"\",\"altitude_m\",\"sun_zenith_deg\",\"view_zenith_deg\",\"view_azimuth_deg\"\r\n"
            "\"1\",0,30,60,0\r\n"
            "\"2\",1500.5,85,90,180\r\n"));
  EXPECT_EQ(reader.columns(), kRadianceColumns);
  const std::vector<CsvRow> rows = readAll(reader);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].values, (std::vector<double>{1500.5, 85.0, 90.0, 180.0}));
  // The row names are not query values: outputs repeat only the named columns.
  EXPECT_EQ(rows[1].texts, (std::vector<std::string>{"1500.5", "85", "90", "180"}));
  EXPECT_EQ(rows[1].line_number, 3);
}

// Exactly what numpy.savetxt(path, a, delimiter=',', header=...) writes.
TEST_F(CsvReaderTest, NumpySavetxtHashHeader) {
  CsvReader reader(
      write("# altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg\n"
            "0.000000000000000000e+00,3.000000000000000000e+01,6.000000000000000000e+01,0.000000000000000000e+00\n"
            "1.500500000000000000e+03,8.500000000000000000e+01,9.000000000000000000e+01,1.800000000000000000e+02\n"));
  EXPECT_EQ(reader.columns(), kRadianceColumns);
  const std::vector<CsvRow> rows = readAll(reader);
  ASSERT_EQ(rows.size(), 2u);
  // The first data row, read while the header was sought, is not lost.
  EXPECT_EQ(rows[0].values, (std::vector<double>{0.0, 30.0, 60.0, 0.0}));
  EXPECT_EQ(rows[0].line_number, 2);
  EXPECT_EQ(rows[1].values, (std::vector<double>{1500.5, 85.0, 90.0, 180.0}));
}

TEST_F(CsvReaderTest, CommentsBeforeARealHeaderStayComments) {
  CsvReader reader(write("# made by a script\naltitude_m,sun_zenith_deg\n0,30\n"));
  EXPECT_EQ(reader.columns(), (std::vector<std::string>{"altitude_m", "sun_zenith_deg"}));
  EXPECT_EQ(readAll(reader).size(), 1u);
}

TEST_F(CsvReaderTest, QuotedCellsFollowRfc4180) {
  CsvReader reader(write("\"a,b\",\"say \"\"hi\"\"\", \"c\" \n\"1.5\", 2 ,\"-3e2\"\n"));
  EXPECT_EQ(reader.columns(), (std::vector<std::string>{"a,b", "say \"hi\"", "c"}));
  const std::vector<CsvRow> rows = readAll(reader);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].values, (std::vector<double>{1.5, 2.0, -300.0}));
  EXPECT_EQ(rows[0].texts, (std::vector<std::string>{"1.5", "2", "-3e2"}));
}

TEST_F(CsvReaderTest, BrokenQuotingNamesLineAndColumn) {
  expectBadInput("a,b\n1,\"2\n", "q.csv:2:2: quoted cell has no closing quote");
  expectBadInput("a,b\n1,\"2\"x\n", "q.csv:2:2: text after the closing quote");
  expectBadInput("\"a\",\"b\n1,2\n", "q.csv:1:2: quoted cell has no closing quote");
}

TEST_F(CsvReaderTest, BadCellsCountTheRowNameColumn) {
  // Column 3 of the file is sun_zenith_deg, even though the row names are
  // not among columns().
  expectBadInput("\"\",\"altitude_m\",\"sun_zenith_deg\"\n\"1\",0,\"abc\"\n", "q.csv:2:3 (sun_zenith_deg): 'abc'");
  expectBadInput("\"\",\"altitude_m\",\"sun_zenith_deg\"\n\"1\",0\n", "q.csv:2:3: 2 cells, the header (line 1) has 3");
  const fs::path p = write("\"\",\"altitude_m\",\"sun_zenith_deg\"\n\"1\",0,95\n");
  CsvReader reader(p);
  CsvRow row;
  ASSERT_TRUE(reader.next(row));
  try {
    reader.requireRange(row, reader.require("sun_zenith_deg"), 0.0, 90.0);
    FAIL() << "out of range accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("q.csv:2:3 (sun_zenith_deg): 95 is out of range"), std::string::npos)
        << e.what();
  }
}

TEST_F(CsvReaderTest, EmptyNamesOtherThanTheFirstAreStillRefused) {
  expectBadInput("altitude_m,\"\"\n0,1\n", "q.csv:1:2: empty column name");
  expectBadInput("\"\"\n1\n", "q.csv:1:1: empty column name");
  expectBadInput("\"a\",a\n1,2\n", "column 'a' appears twice");
}

// An optional column (distance_m, the moon's) may leave a cell empty, as a
// spreadsheet writes a row that does not use it: it reads as the column's
// absence. Required columns still refuse an empty cell, and so do optional
// ones that were not declared so.
TEST_F(CsvReaderTest, EmptyCellsOfOptionalColumnsReadAsTheirAbsence) {
  const fs::path p = write("altitude_m,distance_m\n0,\n1000, \n2000,\"\"\n3000,5e3\n");
  CsvReader reader(p);
  EXPECT_EQ(reader.findOptional("distance_m", 0.0), 1u);
  EXPECT_FALSE(reader.findOptional("moon_separation_deg", 0.0));
  const std::vector<CsvRow> rows = readAll(reader);
  ASSERT_EQ(rows.size(), 4u);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(rows[i].values[1], 0.0) << i;
  EXPECT_EQ(rows[1].texts[1], "");  // written back empty, as every cell is trimmed
  EXPECT_EQ(rows[3].values[1], 5000.0);
  expectBadInput("altitude_m,distance_m\n,5\n", "q.csv:2:1 (altitude_m): '' is not a finite number");
  expectBadInput("altitude_m,distance_m\n0,\n", "q.csv:2:2 (distance_m): '' is not a finite number");
}

TEST_F(CsvReaderTest, HashHeaderWithoutRowsIsNoRows) {
  // A lone '#' line is a comment, not a header: there is nothing to read.
  expectBadInput("# altitude_m,sun_zenith_deg\n", "no header row");
}

}  // namespace
}  // namespace skybake
