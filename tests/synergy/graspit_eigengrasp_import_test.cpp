#include "pmdplan/synergy/graspit_eigengrasp_import.hpp"

#include <gtest/gtest.h>

#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

JointLimits graspitHand() { return {{"spread", -0.5, 0.5}, {"f1", 0.0, 2.0}, {"f2", 0.0, 2.0}, {"f3", 0.0, 1.0}}; }

// A small file in GraspIt's format: 3 dimensions (f1, f2, spread), two eigengrasps.
const char* kOrthogonalFile = R"(<?xml version="1.0" ?>
<EigenGrasps dimensions="3">
  <EG>
    <EigenValue value="0.25"/>
    <DimVals d0="1" d1="1" d2="0"/>
  </EG>
  <EG>
    <EigenValue value="0.04"/>
    <DimVals d2="2"/>
  </EG>
  <ORIGIN>
    <EigenValue value="0.5"/>
    <DimVals d0="0.5" d1="1.5" d2="-0.25"/>
  </ORIGIN>
</EigenGrasps>
)";

TEST(GraspItImport, MeanAndDirectionsInNormalisedJointUnits) {
  test::TempDir dir;
  const auto path = dir.write("eigen.xml", kOrthogonalFile);
  const GraspItImport imported = importGraspItEigengrasps(path, {"f1", "f2", "spread"}, graspitHand());
  const SynergyModel& model = imported.model;
  ASSERT_EQ(model.jointCount(), 4);
  ASSERT_EQ(model.directionCount(), 2);
  // ORIGIN: f1 0.5 of [0, 2] -> 0.25; f2 1.5 -> 0.75; spread -0.25 of [-0.5, 0.5] -> 0.25; f3 held mid-range.
  EXPECT_DOUBLE_EQ(model.mean(0), 0.25);
  EXPECT_DOUBLE_EQ(model.mean(1), 0.25);
  EXPECT_DOUBLE_EQ(model.mean(2), 0.75);
  EXPECT_DOUBLE_EQ(model.mean(3), 0.5);
  // Eigengrasp 1 moves f1 and f2 equally in rad; both have the same range, so also in normalised units.
  EXPECT_TRUE(model.directions.col(0).isApprox(Eigen::Vector4d(0, 1, 1, 0).normalized()));
  EXPECT_TRUE(model.directions.col(1).isApprox(Eigen::Vector4d(1, 0, 0, 0)));
  // sigma = sqrt(eigenvalue) * length in normalised units: (1/sqrt 2 per rad) / 2 rad range.
  EXPECT_NEAR(model.sigma(0), 0.5 * std::sqrt(0.5) / 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(model.sigma(1), 0.2 * 1.0, 1e-12);
  EXPECT_NEAR(model.varianceFraction(0), 0.25 / 0.29, 1e-12);
  EXPECT_TRUE(model.orthonormal);
  EXPECT_TRUE(model.ownAxisJoints.empty());
  EXPECT_NE(model.provenance.find("eigen.xml"), std::string::npos);
}

TEST(GraspItImport, ScalingByJointRangesCanMakeABasisNonOrthogonal) {
  // Orthogonal in rad, but f1 and f3 have different ranges: no longer orthogonal when normalised.
  const std::string xml = R"(<EigenGrasps dimensions="2">
  <EG><EigenValue value="0.3"/><DimVals d0="1" d1="1"/></EG>
  <EG><EigenValue value="0.1"/><DimVals d0="1" d1="-1"/></EG>
  <ORIGIN><DimVals d0="1" d1="0.5"/></ORIGIN>
</EigenGrasps>)";
  const GraspItImport imported = parseGraspItEigengrasps(xml, "g.xml", {"f1", "f3"}, graspitHand());
  EXPECT_FALSE(imported.model.orthonormal);
  bool said = false;
  for (const auto& note : imported.notes) said = said || note.find("least squares") != std::string::npos;
  EXPECT_TRUE(said);
  EXPECT_NEAR(imported.model.directions.col(0).norm(), 1.0, 1e-12);
}

TEST(GraspItImport, ReordersByEigenvalueAndSaysSo) {
  const std::string xml = R"(<EigenGrasps dimensions="1">
  <EG><EigenValue value="0.1"/><DimVals d0="1"/></EG>
  <EG><EigenValue value="0.3"/><DimVals d0="-1"/></EG>
</EigenGrasps>)";
  EXPECT_THROW(parseGraspItEigengrasps(xml, "g.xml", {"f1"}, graspitHand()),
               InputError);  // two parallel vectors: dependent
  const std::string two = R"(<EigenGrasps dimensions="2">
  <EG><EigenValue value="0.1"/><DimVals d0="1"/></EG>
  <EG><EigenValue value="0.3"/><DimVals d1="1"/></EG>
</EigenGrasps>)";
  const GraspItImport imported = parseGraspItEigengrasps(two, "g.xml", {"f1", "f2"}, graspitHand());
  EXPECT_GT(imported.model.sigma(0), imported.model.sigma(1));
  EXPECT_DOUBLE_EQ(imported.model.directions(2, 0), 1.0);
  EXPECT_DOUBLE_EQ(imported.model.mean(1), 0.5);  // no ORIGIN: mid-range, as GraspIt does
}

TEST(GraspItImport, BadInputNamesFileAndLine) {
  test::expectInputError(
      [] {
        parseGraspItEigengrasps("<EigenGrasps dimensions=\"3\">\n<EG>\n</EigenGrasps>", "g.xml", {"f1", "f2", "f3"},
                                graspitHand());
      },
      "g.xml", "line 2", "XML error");
  test::expectInputError(
      [] {
        parseGraspItEigengrasps(kOrthogonalFile, "g.xml", {"f1", "f2"}, graspitHand());
      },
      "g.xml", "line 2 (dimensions)", "3 dimensions but 2 joints");
  test::expectInputError(
      [] {
        parseGraspItEigengrasps(kOrthogonalFile, "g.xml", {"f1", "f2", "wrist"}, graspitHand());
      },
      "", "joints", "'wrist' (dimension 2) is not one of the hand joints");
  std::string beyond = kOrthogonalFile;
  beyond.replace(beyond.find("d1=\"1.5\""), 8, "d1=\"2.5\"");
  test::expectInputError(
      [&] {
        parseGraspItEigengrasps(beyond, "g.xml", {"f1", "f2", "spread"}, graspitHand());
      },
      "g.xml", "line 13 (ORIGIN.d1)", "beyond the limits");
  std::string notNumber = kOrthogonalFile;
  notNumber.replace(notNumber.find("d2=\"2\""), 6, "d2=\"x\"");
  test::expectInputError(
      [&] {
        parseGraspItEigengrasps(notNumber, "g.xml", {"f1", "f2", "spread"}, graspitHand());
      },
      "g.xml", "line 9 (eigengrasp 2.d2)", "not a number");
}

}  // namespace
}  // namespace pmdplan
