#include "pmdplan/io/files/path_csv.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "pmdplan/core/atomic_file.hpp"

namespace pmdplan {
namespace {

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(PathCsv, HeaderThenOneWaypointPerRow) {
  const std::vector<std::string> names = {"a1", "a2", "thumb_base"};
  const std::vector<Configuration> points = {Eigen::Vector3d(0.1, -2.0, 1.0 / 3.0), Eigen::Vector3d(0.0, 1e-9, 3.0)};
  const std::string text = formatPathCsv(names, points);
  const std::vector<std::string> lines = splitLines(text);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "a1,a2,thumb_base");
  EXPECT_EQ(lines[2], "0,1e-09,3");
  // Every value reads back exactly.
  std::istringstream row(lines[1]);
  for (int k = 0; k < 3; ++k) {
    std::string cell;
    std::getline(row, cell, ',');
    EXPECT_EQ(std::stod(cell), points[0][k]);
  }
  EXPECT_EQ(text.back(), '\n');
}

TEST(PathCsv, QuotesAwkwardNames) {
  const std::string text = formatPathCsv({"plain", "with,comma", "say \"hi\""}, {Eigen::Vector3d(1, 2, 3)});
  EXPECT_EQ(splitLines(text)[0], "plain,\"with,comma\",\"say \"\"hi\"\"\"");
}

TEST(PathCsv, RejectsMismatchedOrNonFiniteRows) {
  EXPECT_THROW(formatPathCsv({"a", "b"}, {Eigen::Vector3d(1, 2, 3)}), std::invalid_argument);
  EXPECT_THROW(formatPathCsv({"a"}, {Eigen::VectorXd::Constant(1, std::nan(""))}), std::invalid_argument);
}

TEST(PathCsv, WritesTheFile) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "pmdplan_path_csv_test.csv";
  const std::vector<Configuration> points = {Eigen::Vector2d(0.25, 0.5), Eigen::Vector2d(1, 2)};
  writePathCsv(file, {"x", "y"}, points);
  EXPECT_EQ(readTextFile(file), formatPathCsv({"x", "y"}, points));
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace pmdplan
