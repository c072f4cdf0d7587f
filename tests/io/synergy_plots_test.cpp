#include "pmdplan/io/figures/synergy_plots.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <stdexcept>

#include "pmdplan/synergy/synergy_model_file.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

/// Postures where ring_proximal follows middle_proximal and index_abduction opposes ring_abduction.
Eigen::MatrixXd correlatedPostures(const JointLimits& joints, int frames) {
  Eigen::MatrixXd postures(frames, static_cast<Eigen::Index>(joints.size()));
  for (int f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / (frames - 1);
    for (std::size_t j = 0; j < joints.size(); ++j) {
      double unit = 0.5;
      if (joints[j].name == "middle_proximal" || joints[j].name == "ring_proximal" ||
          joints[j].name == "index_abduction")
        unit = t;
      if (joints[j].name == "ring_abduction") unit = 1.0 - t;
      postures(f, static_cast<Eigen::Index>(j)) = joints[j].denormalise(unit);
    }
  }
  return postures;
}

TEST(SynergyPlots, TheVarianceFigureHasABarPerPmdTheCumulativeLineAndThePapersMarks) {
  const SynergyModel model = loadSynergyModel(defaultSynergyModelPath("sah_tx90"));
  const std::string svg = cumulativeVarianceSvg(model);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(count(svg, "fill=\"#8fb3dc\"/>"), static_cast<std::size_t>(model.directionCount()) + 1)
      << "bars and the legend's swatch";
  EXPECT_EQ(count(svg, "<circle"), static_cast<std::size_t>(model.directionCount()));
  EXPECT_EQ(count(svg, "l6 6l-6 6l-6 -6z"), 3u) << "the paper's 1, 2 and 3 PMD values";
  EXPECT_NE(svg.find(">100.0</text>"), std::string::npos) << "all directions together carry all the variance";
  EXPECT_NE(svg.find("SYNTHETIC"), std::string::npos) << "the provenance is on the figure";
  EXPECT_EQ(svg, cumulativeVarianceSvg(model));
}

TEST(SynergyPlots, TheJointPairFigureShowsEachFigure7PairWithItsCorrelation) {
  const SynergyModel model = loadSynergyModel(defaultSynergyModelPath("sah_tx90"));
  const Eigen::MatrixXd postures = correlatedPostures(model.joints, 500);
  const std::string svg = jointPairsSvg(postures, model.joints, {.maxScatterPoints = 100});
  EXPECT_EQ(count(svg, "<path fill=\"none\" stroke=\"#1f5fa8\""), 6u);
  EXPECT_EQ(count(svg, "h0"), 600u) << "100 points in each of six panels";
  EXPECT_NE(svg.find("middle_proximal  vs  ring_proximal"), std::string::npos);
  EXPECT_NE(svg.find("r = +1.00  (paper's signs: +1.00)   paper: positive"), std::string::npos);
  EXPECT_NE(svg.find("r = -1.00  (paper's signs: -1.00)   paper: negative"), std::string::npos);
  EXPECT_NE(svg.find("r = n/a"), std::string::npos) << "a joint that never moves has no correlation";
  EXPECT_THROW(jointPairsSvg(postures.leftCols(3), model.joints), std::invalid_argument);
}

TEST(SynergyPlots, WritesBothFiguresOrOnlyTheVarianceWithoutPostures) {
  const SynergyModel model = loadSynergyModel(defaultSynergyModelPath("sah_tx90"));
  test::TempDir dir;
  auto files = writeSynergyPlots(dir.path() / "plots", model, correlatedPostures(model.joints, 10), model.joints);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1].filename(), "joint_pairs.svg");
  EXPECT_TRUE(std::filesystem::is_regular_file(files[1]));
  files = writeSynergyPlots(dir.path() / "model-only", model, {}, model.joints);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].filename(), "cumulative_variance.svg");
}

}  // namespace
}  // namespace pmdplan
