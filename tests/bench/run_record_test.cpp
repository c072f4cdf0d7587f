#include "pmdplan/bench/run_record.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pmdplan {
namespace {

RunRecord solvedRecord() {
  RunRecord r;
  r.task = "can_on_table";
  r.planner = "ompl:RRTConnect";
  r.run = 3;
  r.seed = 4;
  r.solved = true;
  r.valid = true;
  r.planningTimeSeconds = 0.1 + 0.2;  // not a short decimal: must come back bit for bit
  r.smoothingTimeSeconds = 1.0 / 3.0;
  r.certificationTimeSeconds = 2.0 / 7.0;
  r.samples = 1234;
  r.armTrials = 321;
  r.maxTrials = 22;
  r.finalArmHalfSize = 0.001 * 6;
  r.nodesByHandDimension = {{2, 7}, {3, 0}, {5, 12}};
  r.roadmapNodes = 77;
  r.pathNodes = 5;
  r.pathLength = std::sqrt(2.0);
  r.collisionChecks = 987654321;
  r.humanLikeness = HumanLikeness{0.0123456789, 0.5, 3.75, IndependentHumanLikeness{0.1 + 0.7, 0.9, -1.0 / 7.0}};
  return r;
}

TEST(RunRecord, EncodingRestoresEveryFieldExactly) {
  const RunRecord r = solvedRecord();
  const std::string text = encodeRunRecord(r);
  EXPECT_EQ(text.find('\n'), std::string::npos);
  const auto back = decodeRunRecord(text);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->task, r.task);
  EXPECT_EQ(back->planner, r.planner);
  EXPECT_EQ(back->run, 3);
  EXPECT_EQ(back->seed, 4u);
  EXPECT_TRUE(back->solved);
  EXPECT_TRUE(back->valid);
  EXPECT_EQ(back->planningTimeSeconds, r.planningTimeSeconds);
  EXPECT_EQ(back->smoothingTimeSeconds, r.smoothingTimeSeconds);
  EXPECT_EQ(back->certificationTimeSeconds, r.certificationTimeSeconds);
  EXPECT_EQ(back->samples, 1234u);
  EXPECT_EQ(back->armTrials, 321u);
  EXPECT_EQ(back->maxTrials, 22u);
  EXPECT_EQ(back->finalArmHalfSize, r.finalArmHalfSize);
  EXPECT_EQ(back->nodesByHandDimension, r.nodesByHandDimension);
  EXPECT_EQ(back->roadmapNodes, 77u);
  EXPECT_EQ(back->pathNodes, 5u);
  EXPECT_EQ(back->pathLength, r.pathLength);
  EXPECT_EQ(back->collisionChecks, 987654321u);
  ASSERT_TRUE(back->humanLikeness.has_value());
  EXPECT_EQ(back->humanLikeness->subspaceDistanceMean, 0.0123456789);
  EXPECT_EQ(back->humanLikeness->mahalanobisMean, 3.75);
  ASSERT_TRUE(back->humanLikeness->independent.has_value());
  EXPECT_EQ(back->humanLikeness->independent->authorsSubspaceDistanceMean, 0.1 + 0.7);
  EXPECT_EQ(back->humanLikeness->independent->authorsSubspaceDistanceMax, 0.9);
  EXPECT_EQ(back->humanLikeness->independent->jointCoupling, -1.0 / 7.0);
  EXPECT_TRUE(back->succeeded());
}

TEST(RunRecord, APathWithoutTheIndependentMeasuresKeepsThemAbsent) {
  RunRecord r = solvedRecord();
  r.humanLikeness->independent.reset();
  const auto back = decodeRunRecord(encodeRunRecord(r));
  ASSERT_TRUE(back.has_value());
  ASSERT_TRUE(back->humanLikeness.has_value());
  EXPECT_FALSE(back->humanLikeness->independent.has_value());
}

TEST(RunRecord, FailureTextWithTabsAndNewlinesSurvives) {
  RunRecord r;
  r.task = "odd\ttask";
  r.planner = "pmd";
  r.failure = "invalid path: segment 3\n(2 -> 3)\tcollides \\ here";
  const std::string text = encodeRunRecord(r);
  EXPECT_EQ(text.find('\n'), std::string::npos);
  const auto back = decodeRunRecord(text);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->task, r.task);
  EXPECT_EQ(back->failure, r.failure);
  EXPECT_FALSE(back->humanLikeness.has_value());
  EXPECT_FALSE(back->succeeded());
}

TEST(RunRecord, RejectsTextThatIsNotARecord) {
  EXPECT_FALSE(decodeRunRecord("").has_value());
  EXPECT_FALSE(decodeRunRecord("hello").has_value());
  std::string text = encodeRunRecord(solvedRecord());
  EXPECT_FALSE(decodeRunRecord(text + "\textra").has_value());
  EXPECT_FALSE(decodeRunRecord("[1, 2]").has_value());
  const auto run = text.find("\"run\":3,");
  ASSERT_NE(run, std::string::npos) << text;
  std::string wrongKind = text;
  wrongKind.replace(run, 8, "\"run\":\"3\",");
  EXPECT_FALSE(decodeRunRecord(wrongKind).has_value());
  std::string unknownKey = text;
  unknownKey.replace(run, 8, "\"runs\":3,");
  EXPECT_FALSE(decodeRunRecord(unknownKey).has_value());
  std::string missing = text;
  missing.erase(run, 8);
  EXPECT_FALSE(decodeRunRecord(missing).has_value());
}

// A journal written before the certification time existed still reads (the time 0), and no
// other key may be missing.
TEST(RunRecord, ARecordWithoutTheCertificationTimeReadsAsAnOlderOne) {
  nlohmann::json json = nlohmann::json::parse(encodeRunRecord(solvedRecord()));
  json.erase("certification_time_s");
  const auto older = decodeRunRecord(json.dump());
  ASSERT_TRUE(older.has_value());
  EXPECT_EQ(older->certificationTimeSeconds, 0.0);
  EXPECT_EQ(older->samples, 1234u);
  json.erase("samples");
  EXPECT_FALSE(decodeRunRecord(json.dump()).has_value());
}

TEST(RunRecord, IsOneJsonObjectWithTheKeysInTheirOrder) {
  const nlohmann::json json = nlohmann::json::parse(encodeRunRecord(solvedRecord()));
  ASSERT_TRUE(json.is_object());
  EXPECT_EQ(json.size(), runRecordKeys().size());
  const std::string text = encodeRunRecord(solvedRecord());
  std::size_t previous = 0;
  for (const char* key : runRecordKeys()) {
    const std::size_t at = text.find("\"" + std::string(key) + "\":");
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_GE(at, previous) << key;
    previous = at;
  }
  EXPECT_EQ(json.at("nodes_by_hand_dimension").dump(), R"({"2":7,"3":0,"5":12})");
  EXPECT_EQ(json.at("human_likeness").at("independent").at("joint_coupling").get<double>(), -1.0 / 7.0);
}

TEST(RunRecord, NonFiniteNumbersComeBack) {
  RunRecord r = solvedRecord();
  r.planningTimeSeconds = HUGE_VAL;
  r.pathLength = std::nan("");
  r.humanLikeness->mahalanobisMean = -HUGE_VAL;
  const auto back = decodeRunRecord(encodeRunRecord(r));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->planningTimeSeconds, HUGE_VAL);
  EXPECT_TRUE(std::isnan(back->pathLength));
  EXPECT_EQ(back->humanLikeness->mahalanobisMean, -HUGE_VAL);
}

}  // namespace
}  // namespace pmdplan
