// Names in CSV fields (docs/history-table.md, RFC 4180): a column name with a comma, a quote or a
// line break is written in double quotes with its quotes doubled, and read back whole; numbers
// and plain names are written as before.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "src/output/csv_table.hpp"
#include "src/output/history_table.hpp"

namespace clinch {
namespace {

namespace fs = std::filesystem;

TEST(CsvField, QuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(csv_field("CTF1@Part-1-1.12"), "CTF1@Part-1-1.12");
  EXPECT_EQ(csv_field("CTF1@Weld, left"), "\"CTF1@Weld, left\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  // The reader trims blanks around unquoted fields and skips '#' lines before the header.
  EXPECT_EQ(csv_field(" padded"), "\" padded\"");
  EXPECT_EQ(csv_field("#note"), "\"#note\"");
}

TEST(CsvQuotedFields, CommaQuoteAndLineBreakInsideQuotes) {
  std::string error;
  const std::optional<CsvTable> table = parse_csv_table(
      "q.csv",
      "step,\"CTF1@Weld, left\", \"a \"\"b\"\"\" ,\"two\nlines\"\n1,2,3,4\n\"5\",6,7,8\n", &error);
  ASSERT_TRUE(table) << error;
  EXPECT_EQ(table->columns,
            (std::vector<std::string>{"step", "CTF1@Weld, left", "a \"b\"", "two\nlines"}));
  ASSERT_EQ(table->rows.size(), 2u);
  EXPECT_EQ(table->rows[0], (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(table->rows[1], (std::vector<double>{5, 6, 7, 8}));
  // The header spans lines 1 and 2: the rows are on lines 3 and 4.
  EXPECT_EQ(table->row_lines, (std::vector<std::size_t>{3, 4}));
}

TEST(CsvQuotedFields, MalformedQuotesAreErrorsWithTheLine) {
  std::string error;
  EXPECT_FALSE(parse_csv_table("q.csv", "a,b\n1,2\n3,\"4\n", &error));
  EXPECT_EQ(error, "q.csv:3: the quoted field that starts on line 3 is not closed");
  EXPECT_FALSE(parse_csv_table("q.csv", "a,\"b\"c\n", &error));
  EXPECT_EQ(error,
            "q.csv:1: text after the closing quote of a field (a quote inside a quoted field is "
            "written twice)");
}

TEST(CsvQuotedFields, HistoryHeaderWithACommaReadsBackAsItsColumns) {
  const fs::path path =
      fs::temp_directory_path() / fmt::format("clinch-csv-quoting-{}.history.csv", getpid());
  {
    HistoryTable table;
    std::string error;
    ASSERT_TRUE(table.open(path, {"CTF1@Weld, left", "CU1@7"}, &error)) << error;
    ASSERT_TRUE(table.write_row(1, 1, 0.5, 0.5, std::vector<double>{-1.25, 3e-7}));
  }
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "step,increment,step_time,total_time,\"CTF1@Weld, left\",CU1@7");
  std::string error;
  const std::optional<CsvTable> table = read_csv_table(path.string(), &error);
  fs::remove(path);
  ASSERT_TRUE(table) << error;
  ASSERT_EQ(table->columns.size(), 6u);
  EXPECT_EQ(table->columns[4], "CTF1@Weld, left");
  ASSERT_EQ(table->rows.size(), 1u);
  EXPECT_EQ(table->rows[0], (std::vector<double>{1, 1, 0.5, 0.5, -1.25, 3e-7}));
}

}  // namespace
}  // namespace clinch
