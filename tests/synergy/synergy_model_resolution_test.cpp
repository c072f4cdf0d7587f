// resolveSynergyModel (synergy/synergy_model_resolution.hpp): the model given, else the robot's
// shipped one, else — as the command needs — an error saying how to get one, or none.
#include "pmdplan/synergy/synergy_model_resolution.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pmdplan/synergy/synergy_model_file.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

TEST(SynergyModelResolution, TheRobotsShippedModelWhenNoneIsGiven) {
  for (const auto need : {SynergyModelNeed::Required, SynergyModelNeed::Optional}) {
    const ResolvedSynergyModel resolved = resolveSynergyModel("sah_tx90", {}, need);
    ASSERT_TRUE(resolved.model);
    EXPECT_EQ(resolved.file, defaultSynergyModelPath("sah_tx90"));
    EXPECT_EQ(resolved.get(), &*resolved.model);
    EXPECT_EQ(formatSynergyModel(*resolved.model), formatSynergyModel(loadSynergyModel(resolved.file)));
  }
}

TEST(SynergyModelResolution, TheGivenFileWinsOverTheShippedModel) {
  const test::TempDir dir;
  SynergyModel model = loadSynergyModel(defaultSynergyModelPath("sah_tx90"));
  model.provenance = "a model of the test's own";
  const auto file = dir.path() / "own.yaml";
  saveSynergyModel(file, model);
  const ResolvedSynergyModel resolved = resolveSynergyModel("sah_tx90", file, SynergyModelNeed::Optional);
  ASSERT_TRUE(resolved.model);
  EXPECT_EQ(resolved.file, file);
  EXPECT_EQ(resolved.model->provenance, "a model of the test's own");
  test::expectInputError(
      [&] { resolveSynergyModel("sah_tx90", dir.path() / "missing.yaml", SynergyModelNeed::Optional); },
      (dir.path() / "missing.yaml").string(), "", "");
}

TEST(SynergyModelResolution, ARobotWithoutAShippedModelIsExplainedOrHasNone) {
  test::expectInputError([] { resolveSynergyModel("robot_without_model", {}, SynergyModelNeed::Required); }, "",
                         "--synergies", "robot 'robot_without_model' has no shipped synergy model");
  const ResolvedSynergyModel none = resolveSynergyModel("robot_without_model", {}, SynergyModelNeed::Optional);
  EXPECT_FALSE(none.model);
  EXPECT_EQ(none.get(), nullptr);
  EXPECT_TRUE(none.file.empty());
}

}  // namespace
}  // namespace pmdplan
