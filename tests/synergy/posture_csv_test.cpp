// The posture table reader: a leading byte order mark is an encoding marker, and no message shows
// a header or cell of the file raw (long ones are measured, control characters escaped).
#include "pmdplan/synergy/posture_csv.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pmdplan/core/input_error.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

const JointLimits kHand = {{"flex", 0.0, 1.5}, {"spread", -0.5, 0.5}};

TEST(PostureCsv, ALeadingByteOrderMarkIsAnEncodingMarker) {
  test::TempDir dir;
  const auto file = dir.write("p.csv",
                              "\xef\xbb\xbf"
                              "flex,spread\n10,-5\n");
  const Eigen::MatrixXd postures = readPostureCsv(file, kHand, PostureUnit::Degrees);
  ASSERT_EQ(postures.rows(), 1);
  EXPECT_NEAR(postures(0, 1), -5.0 * 3.14159265358979 / 180.0, 1e-12);
}

TEST(PostureCsv, HeadersAndCellsAreMeasuredOrEscapedNeverShownRaw) {
  test::TempDir dir;
  const std::string secret = "root:$6$saltsalt$" + std::string(86, 'h') + ":19000:0:99999:7:::";
  const auto shadow = dir.write("shadow.csv", secret + "\n");
  try {
    readPostureCsv(shadow, kHand, PostureUnit::Degrees);
    ADD_FAILURE() << "an unknown column was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).find("saltsalt"), std::string::npos) << error.what();
    EXPECT_THAT(error.message(), ::testing::HasSubstr("header column a text of 122 characters"));
  }
  const auto escape = dir.write("escape.csv", "flex,\x1b[2Jspread\n");
  test::expectInputError([&] { readPostureCsv(escape, kHand, PostureUnit::Degrees); }, escape.string(), "line 1",
                         "header column '\\x1b[2Jspread' is not a hand joint");
  const auto cell = dir.write("cell.csv", "flex,spread\n10," + secret + "\n");
  try {
    readPostureCsv(cell, kHand, PostureUnit::Degrees);
    ADD_FAILURE() << "a bad cell was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).find("saltsalt"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace pmdplan
