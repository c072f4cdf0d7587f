#include "pmdplan/synergy/hand_mapping_file.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <set>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/glove/cyberglove_sensors.hpp"
#include "sah_hand_joints.hpp"
#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

const std::string kPaperMapping = std::string(PMDPLAN_TEST_DATA_DIR) + "/glove/cyberglove22_to_sah.yaml";

TEST(HandMappingFile, ThePapersTable1) {
  const HandMapping mapping = loadHandMapping(kPaperMapping);
  const auto rules = rulesForJoints(mapping, test::sahHandJoints());  // covers every SAH joint once
  ASSERT_EQ(rules.size(), 13u);
  const int thumbRoll = cyberGloveSensorIndex("ThumbRotate");
  EXPECT_EQ(rules[0]->terms.at(0).sensor, thumbRoll);  // thumb_base
  EXPECT_EQ(rules[1]->terms.at(0).sensor, thumbRoll);  // thumb_abduction
  EXPECT_TRUE(rules[7]->isConstant());                 // middle_abduction
  EXPECT_EQ(rules[7]->offset, 0.0);
  EXPECT_EQ(rules[4]->terms.at(0).sensor, cyberGloveSensorIndex("MiddleIndexAb"));  // index abduction: sensor j
  EXPECT_EQ(rules[10]->terms.at(0).sensor, cyberGloveSensorIndex("RingMiddleAb"));  // ring abduction: sensor n
  // 11 sensors drive 13 joints.
  std::set<int> sensors;
  for (const auto* rule : rules)
    for (const auto& term : rule->terms) sensors.insert(term.sensor);
  EXPECT_EQ(sensors.size(), 11u);
  // Thumb roll 0 -> base 0, abduction +15 deg; roll 90 deg -> base 90, abduction -15 deg.
  const double quarter = std::numbers::pi / 2;
  EXPECT_NEAR(rules[1]->offset, 15 * std::numbers::pi / 180, 1e-15);
  EXPECT_NEAR(rules[1]->offset + rules[1]->terms[0].gain * quarter, -15 * std::numbers::pi / 180, 1e-15);
}

TEST(HandMappingFile, RoundTripsToIdenticalRules) {
  const HandMapping mapping = loadHandMapping(kPaperMapping);
  const std::string text = formatHandMapping(mapping);
  const HandMapping back = parseHandMapping(text, "again.yaml");
  ASSERT_EQ(back.rules.size(), mapping.rules.size());
  for (std::size_t i = 0; i < mapping.rules.size(); ++i) {
    EXPECT_EQ(back.rules[i].joint, mapping.rules[i].joint);
    EXPECT_EQ(back.rules[i].offset, mapping.rules[i].offset);
    ASSERT_EQ(back.rules[i].terms.size(), mapping.rules[i].terms.size());
    for (std::size_t t = 0; t < mapping.rules[i].terms.size(); ++t) {
      EXPECT_EQ(back.rules[i].terms[t].sensor, mapping.rules[i].terms[t].sensor);
      EXPECT_EQ(back.rules[i].terms[t].gain, mapping.rules[i].terms[t].gain);
    }
  }
  EXPECT_EQ(back.description, mapping.description);
  EXPECT_EQ(formatHandMapping(back), text);
}

TEST(HandMappingFile, SeveralSensorsPerJoint) {
  const auto mapping =
      parseHandMapping("joints:\n  - {joint: a, sensors: {IndexMPJ: 0.5, IndexPIJ: 0.25}, offset: -0.1}\n", "m.yaml");
  ASSERT_EQ(mapping.rules.at(0).terms.size(), 2u);
  EXPECT_EQ(mapping.rules[0].terms[1].gain, 0.25);
  EXPECT_EQ(mapping.rules[0].offset, -0.1);
  EXPECT_EQ(mapping.rules[0].sourceLine, 2);
}

TEST(HandMappingFile, UnknownSensorNamesTheLine) {
  test::expectInputError(
      [] {
        parseHandMapping("joints:\n  - {joint: a, sensors: {IndexMPJ: 1}}\n  - {joint: b, sensors: {IndexMCP: 1}}\n",
                         "m.yaml");
      },
      "m.yaml", "line 3 (joint b)", "unknown sensor 'IndexMCP'");
}

TEST(HandMappingFile, UnknownJointIsFoundAgainstTheRobotWithItsLine) {
  std::string text = readTextFile(kPaperMapping);
  text.replace(text.find("joint: ring_medium"), 18, "joint: ring_distal");
  const HandMapping mapping = parseHandMapping(text, "mine.yaml");
  test::expectInputError([&] { rulesForJoints(mapping, test::sahHandJoints()); }, "mine.yaml",
                         "line 29 (joint ring_distal)", "unknown joint 'ring_distal'");
}

TEST(HandMappingFile, MalformedRulesNameTheLine) {
  test::expectInputError(
      [] { parseHandMapping("joints:\n  - {joint: a, sensors: {IndexMPJ: 1}, constant: 0}\n", "m.yaml"); }, "m.yaml",
      "line 2 (joint a)", "either sensors");
  test::expectInputError(
      [] { parseHandMapping("joints:\n  - {joint: a, constant: 0}\n  - {joint: a, constant: 0}\n", "m.yaml"); },
      "m.yaml", "line 3 (joint a)", "listed twice");
  test::expectInputError([] { parseHandMapping("joints:\n  - {joint: a, sensors: {IndexMPJ: one}}\n", "m.yaml"); },
                         "m.yaml", "joints[0].sensors.IndexMPJ (line 2)", "expected a gain, got 'one'");
  test::expectInputError([] { parseHandMapping("joints:\n  - {joint: a, sensor: IndexMPJ}\n", "m.yaml"); }, "m.yaml",
                         "line 2", "unknown key 'sensor'");
}

}  // namespace
}  // namespace pmdplan
