// `pmdplan synergies ... --plots DIR`, run as the real program: the figures land in DIR, from a
// recording both (Fig. 10 and Fig. 7), from a model file the variance alone; the normal output
// (here JSON) is left as it was.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::runCli;
using ::testing::HasSubstr;

const std::filesystem::path kDataDir = PMDPLAN_TEST_DATA_DIR;

using test::contents;
using test::quoted;

TEST(SynergyPlotsCli, ARecordingGivesBothFiguresBesideItsUsualOutput) {
  test::TempDir dir;
  const auto plots = dir.path() / "plots";
  const auto result = runCli("synergies " + quoted(kDataDir / "glove" / "synthetic_operator_sample.csv") +
                             " --json --plots " + quoted(plots));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(nlohmann::json::accept(result.out)) << "the figures do not disturb the JSON on stdout";
  EXPECT_THAT(result.err, HasSubstr("joint_pairs.svg"));
  const std::string pairs = contents(plots / "joint_pairs.svg");
  EXPECT_THAT(pairs, HasSubstr("middle_proximal  vs  ring_proximal"));
  EXPECT_THAT(pairs, HasSubstr("thumb_base  vs  ring_medium"));
  EXPECT_THAT(contents(plots / "cumulative_variance.svg"), HasSubstr("the paper's Fig. 10"));
}

TEST(SynergyPlotsCli, AModelFileGivesTheVarianceFigure) {
  test::TempDir dir;
  const auto plots = dir.path() / "plots";
  const auto result = runCli("synergies --show " + quoted(kDataDir / "synergies" / "sah_tx90_default.yaml") +
                             " --plots " + quoted(plots));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(plots / "cumulative_variance.svg"));
  EXPECT_FALSE(std::filesystem::exists(plots / "joint_pairs.svg"));
}

}  // namespace
}  // namespace pmdplan
