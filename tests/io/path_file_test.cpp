#include "pmdplan/io/files/path_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>

#include "planning/toy_problem.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/json_text.hpp"
#include "pmdplan/planning/pmd_roadmap_planner.hpp"

namespace pmdplan {
namespace {

PathFile samplePath() {
  PathFile path;
  path.task = "can_on_table";
  path.planner = "pmd";
  path.seed = 18446744073709551615ull;  // the largest seed survives
  path.jointNames = {"a1", "a2", "index_medium"};
  path.points = {Eigen::Vector3d(0.1, -1.5707963267948966, 1.0 / 3.0), Eigen::Vector3d(-0.0, 1e-300, 2.0),
                 Eigen::Vector3d(3.0, 0.5, 0.25)};
  path.mimic = {{"index_distal", "index_medium", 1.0, 0.0}, {"thumb_distal", "thumb_medium", 0.5, -0.1}};
  PlanningStatistics& s = path.statistics;
  s.status = PlannerStatus::Solved;
  s.planningTime = 0.123;
  s.smoothingTime = 0.004;
  s.finalArmHalfSize = 0.002;
  s.sweeps = 2;
  s.maxTrials = 23;
  s.samples = 2000;
  s.armTrials = 699;
  s.roadmapNodes = 29;
  s.roadmapEdges = 28;
  s.nodesByHandDimension = {{2, 7}, {3, 8}, {5, 12}};
  s.pathNodes = 3;
  s.pathNodesBeforeSmoothing = 6;
  s.pathLength = 1.25;
  s.pathLengthBeforeSmoothing = 2.5;
  s.stateChecks = 2100;
  s.motionChecks = 15000;
  return path;
}

void expectSamePath(const PathFile& a, const PathFile& b, bool timings) {
  EXPECT_EQ(a.task, b.task);
  EXPECT_EQ(a.planner, b.planner);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.jointNames, b.jointNames);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i], b.points[i]) << "point " << i;
    for (Eigen::Index k = 0; k < a.points[i].size(); ++k)
      EXPECT_EQ(std::signbit(a.points[i][k]), std::signbit(b.points[i][k]));
  }
  EXPECT_EQ(a.mimic, b.mimic);
  EXPECT_EQ(a.closingFrom, b.closingFrom);
  const PlanningStatistics& s = a.statistics;
  const PlanningStatistics& t = b.statistics;
  EXPECT_EQ(s.status, t.status);
  EXPECT_EQ(s.finalArmHalfSize, t.finalArmHalfSize);
  EXPECT_EQ(s.sweeps, t.sweeps);
  EXPECT_EQ(s.maxTrials, t.maxTrials);
  EXPECT_EQ(s.samples, t.samples);
  EXPECT_EQ(s.armTrials, t.armTrials);
  EXPECT_EQ(s.roadmapNodes, t.roadmapNodes);
  EXPECT_EQ(s.roadmapEdges, t.roadmapEdges);
  EXPECT_EQ(s.nodesByHandDimension, t.nodesByHandDimension);
  EXPECT_EQ(s.pathNodes, t.pathNodes);
  EXPECT_EQ(s.pathNodesBeforeSmoothing, t.pathNodesBeforeSmoothing);
  EXPECT_EQ(s.pathLength, t.pathLength);
  EXPECT_EQ(s.pathLengthBeforeSmoothing, t.pathLengthBeforeSmoothing);
  EXPECT_EQ(s.stateChecks, t.stateChecks);
  EXPECT_EQ(s.motionChecks, t.motionChecks);
  if (timings) {
    EXPECT_EQ(s.planningTime, t.planningTime);
    EXPECT_EQ(s.smoothingTime, t.smoothingTime);
  }
}

TEST(PathFile, RoundTripsExactly) {
  const PathFile path = samplePath();
  const std::string text = formatPathFile(path);
  const PathFile back = parsePathFile(text, "path.json");
  expectSamePath(path, back, false);
  EXPECT_EQ(back.statistics.planningTime, 0.0) << "timings are left out by default";
  EXPECT_EQ(formatPathFile(back), text) << "reading and writing again gives the same bytes";

  const PathFile timed = parsePathFile(formatPathFile(path, {true}), "path.json");
  expectSamePath(path, timed, true);
}

TEST(PathFile, HasTheKeysOfTheIssueInOrder) {
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(formatPathFile(samplePath()));
  std::vector<std::string> keys;
  for (auto item = json.begin(); item != json.end(); ++item) keys.push_back(item.key());
  EXPECT_EQ(keys,
            (std::vector<std::string>{"task", "planner", "seed", "joint_names", "points", "mimic", "statistics"}));
  EXPECT_EQ(json["mimic"]["thumb_distal"], nlohmann::ordered_json::parse(R"(["thumb_medium", 0.5, -0.1])"));
  EXPECT_EQ(json["points"][0]["positions"].size(), 3u);
  EXPECT_FALSE(json["statistics"].contains("planning_time_s"));
  EXPECT_EQ(json["statistics"]["collision_checks"], 17100);
}

// A grasp path (docs/grasp_goals.md): the phases sit after the points and round-trip.
TEST(PathFile, AGraspPathMarksItsApproachAndClosing) {
  PathFile path = samplePath();
  path.closingFrom = 1;
  const std::string text = formatPathFile(path);
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
  std::vector<std::string> keys;
  for (auto item = json.begin(); item != json.end(); ++item) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"task", "planner", "seed", "joint_names", "points", "phases", "mimic",
                                            "statistics"}));
  EXPECT_EQ(json["phases"], nlohmann::ordered_json::parse(R"({"approach": [0, 1], "closing": [1, 2]})"));
  const PathFile back = parsePathFile(text, "grasp.json");
  expectSamePath(path, back, false);
  EXPECT_EQ(formatPathFile(back), text);
  for (std::size_t k : {0u, 2u}) {
    path.closingFrom = k;
    EXPECT_THROW(formatPathFile(path), std::invalid_argument) << k;
  }
}

TEST(PathFile, WritesAtomicallyAndReadsBack) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "pmdplan_path_file_test.json";
  writePathFile(file, samplePath());
  EXPECT_EQ(readTextFile(file), formatPathFile(samplePath()));
  expectSamePath(readPathFile(file), samplePath(), false);
  std::filesystem::remove(file);
}

TEST(PathFile, WriterRejectsPointsOfTheWrongSize) {
  PathFile path = samplePath();
  path.points[1] = Eigen::Vector2d(0, 0);
  EXPECT_THROW(formatPathFile(path), std::invalid_argument);
}

// The issue's "same task and seed -> byte-identical path file", for the library: two runs of the
// planner with one seed give the same file.
TEST(PathFile, TheSameSeedGivesAByteIdenticalFile) {
  const auto plannedFile = [](std::uint64_t seed) {
    toy::WallStateValidator stateValidator;
    toy::WallMotionValidator motionValidator;
    const SynergyModel model = toy::synergyModel();
    PlannerSettings parameters;
    parameters.seed = seed;
    PmdRoadmapPlanner planner(toy::space(), stateValidator, motionValidator,
                              makeHandSampler(HandSamplingMode::Synergy, toy::space(), &model), parameters);
    planner.setStartAndGoal(toy::start(), toy::goal());
    EXPECT_EQ(planner.solve(), PlannerStatus::Solved);
    PathFile path;
    path.task = "toy";
    path.planner = planner.handSampler().name();
    path.seed = seed;
    path.jointNames = planner.space().jointNames();
    path.points = planner.path();
    path.statistics = planner.statistics();
    return formatPathFile(path);
  };
  const std::string first = plannedFile(11);
  EXPECT_EQ(plannedFile(11), first);
  EXPECT_NE(plannedFile(12), first);
}

/// Parses `samplePath()` after `edit` changed its JSON, expecting an InputError on `field`.
void expectBadFile(const std::function<void(nlohmann::ordered_json&)>& edit, const std::string& field) {
  nlohmann::ordered_json json = nlohmann::ordered_json::parse(formatPathFile(samplePath()));
  edit(json);
  try {
    parsePathFile(json.dump(), "bad.json");
    ADD_FAILURE() << "accepted a file with a bad " << field;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "bad.json");
    EXPECT_EQ(error.field(), field) << error.what();
  }
}

TEST(PathFile, BadFilesNameTheFileAndTheKey) {
  using J = nlohmann::ordered_json;
  expectBadFile([](J& j) { j.erase("points"); }, "points");
  expectBadFile([](J& j) { j["colour"] = "red"; }, "colour");
  expectBadFile([](J& j) { j["task"] = 3; }, "task");
  expectBadFile([](J& j) { j["planner"] = ""; }, "planner");
  expectBadFile([](J& j) { j["seed"] = "1"; }, "seed");
  expectBadFile([](J& j) { j["seed"] = -1; }, "seed");
  expectBadFile([](J& j) { j["seed"] = 1.5; }, "seed");
  expectBadFile([](J& j) { j["joint_names"] = "a1"; }, "joint_names");
  expectBadFile([](J& j) { j["joint_names"][2] = "a1"; }, "joint_names[2]");
  expectBadFile([](J& j) { j["joint_names"][1] = 7; }, "joint_names[1]");
  expectBadFile([](J& j) { j["points"] = J::array({j["points"][0]}); }, "points");
  expectBadFile([](J& j) { j["points"][1] = J::array({1, 2, 3}); }, "points[1]");
  expectBadFile([](J& j) { j["points"][1]["velocities"] = J::array(); }, "points[1].velocities");
  expectBadFile([](J& j) { j["points"][2]["positions"].push_back(0.0); }, "points[2].positions");
  expectBadFile([](J& j) { j["points"][0]["positions"][1] = "0.5"; }, "points[0].positions[1]");
  expectBadFile([](J& j) { j["points"][0]["positions"][1] = nullptr; }, "points[0].positions[1]");
  expectBadFile([](J& j) { j["mimic"] = J::array(); }, "mimic");
  expectBadFile([](J& j) { j["mimic"]["index_distal"] = J::array({"index_medium", 1}); }, "mimic.index_distal");
  expectBadFile([](J& j) { j["mimic"]["index_distal"][2] = "0"; }, "mimic.index_distal[2]");
  expectBadFile([](J& j) { j["mimic"]["a1"] = J::array({"a2", 1, 0}); }, "mimic.a1");
  expectBadFile([](J& j) { j["statistics"].erase("samples"); }, "statistics.samples");
  expectBadFile([](J& j) { j["statistics"]["status"] = "great"; }, "statistics.status");
  expectBadFile([](J& j) { j["statistics"]["roadmap_nodes"] = -3; }, "statistics.roadmap_nodes");
  expectBadFile([](J& j) { j["statistics"]["collision_checks"] = 5; }, "statistics.collision_checks");
  expectBadFile([](J& j) { j["statistics"]["nodes_by_hand_dimension"]["two"] = 1; },
                "statistics.nodes_by_hand_dimension.two");
  expectBadFile([](J& j) { j["statistics"]["bogus"] = 1; }, "statistics.bogus");
  expectBadFile([](J& j) { j["phases"] = J::array(); }, "phases");
  expectBadFile([](J& j) { j["phases"] = J::parse(R"({"approach": [0, 1]})"); }, "phases.closing");
  expectBadFile([](J& j) { j["phases"] = J::parse(R"({"approach": [0, 1], "closing": [2, 2]})"); }, "phases");
  expectBadFile([](J& j) { j["phases"] = J::parse(R"({"approach": [0, 2], "closing": [2, 2]})"); }, "phases");
  expectBadFile([](J& j) { j["phases"] = J::parse(R"({"approach": [0, 1], "closing": [1]})"); }, "phases.closing");
  expectBadFile([](J& j) { j["phases"] = J::parse(R"({"approach": [0, -1], "closing": [1, 2]})"); },
                "phases.approach[1]");
}

TEST(PathFile, NotJsonOrNotAnObject) {
  try {
    parsePathFile("{\"task\": ", "broken.json");
    ADD_FAILURE();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "broken.json");
    EXPECT_NE(std::string(error.what()).find("not valid JSON"), std::string::npos);
  }
  EXPECT_THROW(parsePathFile("[1, 2]", "array.json"), InputError);
  EXPECT_THROW(readPathFile("/nonexistent/dir/path.json"), InputError);
}

}  // namespace
}  // namespace pmdplan
