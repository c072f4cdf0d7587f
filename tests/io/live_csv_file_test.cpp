#include "pmdplan/io/files/live_csv_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "pmdplan/core/input_error.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(LiveCsvFile, RowsAreInThePartialFileAsTheyComeAndFinishRenamesIt) {
  test::TempDir dir;
  const auto target = dir.path() / "rec.csv";
  dir.write("rec.csv", "an earlier recording\n");
  LiveCsvFile file(target, "-o", {"note"}, "time_s,a");
  file.addRow("0,1");
  EXPECT_EQ(contents(dir.path() / "rec.csv.partial"), "# note\ntime_s,a\n0,1\n");  // flushed, readable now
  EXPECT_EQ(contents(target), "an earlier recording\n");
  file.addRow("0.01,2");
  EXPECT_EQ(file.finish(), 2);
  EXPECT_EQ(contents(target), "# note\ntime_s,a\n0,1\n0.01,2\n");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "rec.csv.partial"));
}

TEST(LiveCsvFile, NoRowsLeaveTheTargetAsItWas) {
  test::TempDir dir;
  const auto target = dir.path() / "rec.csv";
  dir.write("rec.csv", "an earlier recording\n");
  {
    LiveCsvFile file(target, "-o", {}, "time_s,a");
    EXPECT_EQ(file.finish(), 0);
  }
  { LiveCsvFile unfinished(target, "-o", {}, "time_s,a"); }
  EXPECT_EQ(contents(target), "an earlier recording\n");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "rec.csv.partial"));
}

TEST(LiveCsvFile, AnUnfinishedFileWithRowsKeepsItsPartialFile) {
  test::TempDir dir;
  {
    LiveCsvFile file(dir.path() / "rec.csv", "-o", {}, "h");
    file.addRow("1");
  }
  EXPECT_EQ(contents(dir.path() / "rec.csv.partial"), "h\n1\n");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "rec.csv"));
}

TEST(LiveCsvFile, AnOutputThatIsAFolderOrAnInputIsAnInputError) {
  test::TempDir dir;
  EXPECT_THROW(LiveCsvFile(dir.path(), "-o", {}, "h"), InputError);
  const auto input = dir.write("in.csv", "x\n");
  EXPECT_THROW(LiveCsvFile(input, "-o", {}, "h", {input}), InputError);
}

}  // namespace
}  // namespace pmdplan
