#include "pmdplan/synergy/synergy_model_file.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>

#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

SynergyModel sampleModel() {
  SynergyModel model;
  model.joints = {{"base", 0.0, 1.5707963267948966}, {"a", -0.26, 0.26}, {"b", -0.07, 1.3}, {"c", 0.07, 1.3}};
  model.ownAxisJoints = {"base"};
  model.mean.resize(4);
  model.mean << 0.7, 0.1 + 0.2, 0.55, 1.0 / 3.0;
  Eigen::MatrixXd seed(3, 2);
  seed << 0.3, 0.8, -0.6, 0.1, 0.5, 0.4;
  const Eigen::MatrixXd q =
      Eigen::HouseholderQR<Eigen::MatrixXd>(seed).householderQ() * Eigen::MatrixXd::Identity(3, 2);
  model.directions = Eigen::MatrixXd::Zero(4, 2);
  model.directions.bottomRows(3) = q;
  model.sigma.resize(2);
  model.sigma << 0.31415926535, 0.1;
  model.varianceFraction.resize(2);
  model.varianceFraction << 0.7, 0.3;
  model.provenance = "test model, \"quoted\"";
  return model;
}

void expectIdentical(const SynergyModel& a, const SynergyModel& b) {
  ASSERT_EQ(a.jointCount(), b.jointCount());
  for (int j = 0; j < a.jointCount(); ++j) {
    EXPECT_EQ(a.joints[static_cast<std::size_t>(j)].name, b.joints[static_cast<std::size_t>(j)].name);
    EXPECT_EQ(a.joints[static_cast<std::size_t>(j)].lower, b.joints[static_cast<std::size_t>(j)].lower);
    EXPECT_EQ(a.joints[static_cast<std::size_t>(j)].upper, b.joints[static_cast<std::size_t>(j)].upper);
  }
  EXPECT_EQ(a.mean, b.mean);  // exact, not approximately
  EXPECT_EQ(a.directions, b.directions);
  EXPECT_EQ(a.sigma, b.sigma);
  EXPECT_EQ(a.varianceFraction, b.varianceFraction);
  EXPECT_EQ(a.ownAxisJoints, b.ownAxisJoints);
  EXPECT_EQ(a.orthonormal, b.orthonormal);
  EXPECT_EQ(a.provenance, b.provenance);
}

TEST(SynergyModelFile, LoadsBackExactly) {
  test::TempDir dir;
  const SynergyModel model = sampleModel();
  saveSynergyModel(dir.path() / "m.yaml", model);
  const SynergyModel back = loadSynergyModel(dir.path() / "m.yaml");
  expectIdentical(model, back);
  EXPECT_EQ(formatSynergyModel(back), formatSynergyModel(model));
}

TEST(SynergyModelFile, TheShippedDefaultModelLoads) {
  const SynergyModel model = loadSynergyModel(defaultSynergyModelPath("sah_tx90"));
  EXPECT_EQ(model.jointCount(), 13);
  EXPECT_EQ(model.directionCount(), 11);
  EXPECT_EQ(model.ownAxisJoints, std::vector<std::string>{"thumb_base"});
  EXPECT_TRUE(model.orthonormal);
  EXPECT_NE(model.provenance.find("SYNTHETIC"), std::string::npos);
  EXPECT_TRUE(model.boxHalfWidths(2.0).isApprox(2.0 * model.sigma));
}

std::string withDirections(const std::string& first, const std::string& second, bool orthonormal = true) {
  return "joints:\n  - {name: a, lower: 0, upper: 1}\n  - {name: b, lower: 0, upper: 1}\n"
         "own_axis_joints: []\northonormal: " +
         std::string(orthonormal ? "true" : "false") +
         "\nmean: [0.5, 0.5]\ndirections:\n"
         "  - {sigma: 0.2, variance_fraction: 0.8, vector: " +
         first +
         "}\n"
         "  - {sigma: 0.1, variance_fraction: 0.2, vector: " +
         second + "}\n";
}

TEST(SynergyModelFile, NonOrthonormalDirectionsNameTheLine) {
  test::expectInputError([] { parseSynergyModel(withDirections("[1, 0]", "[0.6, 0.8]"), "m.yaml"); }, "m.yaml",
                         "directions[1] (line 9)", "directions 1 and 2 are not orthonormal");
}

TEST(SynergyModelFile, ANonOrthogonalBasisMarkedSoIsAccepted) {
  const SynergyModel model = parseSynergyModel(withDirections("[1, 0]", "[0.6, 0.8]", false), "m.yaml");
  EXPECT_FALSE(model.orthonormal);
  test::expectInputError([] { parseSynergyModel(withDirections("[1, 0]", "[-1, 0]", false), "m.yaml"); }, "m.yaml",
                         "line 8", "linearly dependent");
}

TEST(SynergyModelFile, DirectionsMustBeUnitVectors) {
  test::expectInputError([] { parseSynergyModel(withDirections("[2, 0]", "[0, 1]"), "m.yaml"); }, "m.yaml",
                         "directions[0] (line 8)", "has length 2");
}

TEST(SynergyModelFile, SizesAndRangesAreChecked) {
  std::string text = withDirections("[1, 0]", "[0, 1]");
  test::expectInputError(
      [&] { parseSynergyModel(std::string(text).replace(text.find("vector: [1, 0]"), 14, "vector: [1]"), "m.yaml"); },
      "m.yaml", "line 8", "1 values for 2 joints");
  test::expectInputError(
      [&] { parseSynergyModel(std::string(text).replace(text.find("[0.5, 0.5]"), 10, "[0.5, 1.5]"), "m.yaml"); },
      "m.yaml", "mean (line 6)", "normalised values lie in [0, 1]");
  test::expectInputError(
      [&] { parseSynergyModel(std::string(text).replace(text.find("sigma: 0.1"), 10, "sigma: -1"), "m.yaml"); },
      "m.yaml", "line 9", "sigma must be zero or positive");
  test::expectInputError(
      [&] {
        parseSynergyModel(std::string(text).replace(text.find("own_axis_joints: []"), 19, "own_axis_joints: [a]"),
                          "m.yaml");
      },
      "m.yaml", "directions[0] (line 8)", "moves own-axis joint a");
  test::expectInputError(
      [&] {
        parseSynergyModel(std::string(text).replace(text.find("own_axis_joints: []"), 19, "own_axis_joints: [z]"),
                          "m.yaml");
      },
      "m.yaml", "own_axis_joints (line 4)", "'z' is not among the joints");
  test::expectInputError([&] { parseSynergyModel(text + "kappa: 2\n", "m.yaml"); }, "m.yaml", "line 10",
                         "unknown key 'kappa'");
}

TEST(SynergyModelFile, ModelsBuiltInCodeAreCheckedOnSave) {
  SynergyModel model = sampleModel();
  model.directions(1, 1) += 0.3;  // no longer unit, no longer orthogonal
  test::TempDir dir;
  EXPECT_THROW(saveSynergyModel(dir.path() / "bad.yaml", model), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "bad.yaml"));
}

}  // namespace
}  // namespace pmdplan
