#include "pmdplan/glove/cyberglove_sensors.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace pmdplan {
namespace {

TEST(CyberGloveSensors, TwentyTwoDistinctNamesInTheGlovesOrder) {
  const auto& names = cyberGloveSensorNames();
  EXPECT_EQ(std::set<std::string_view>(names.begin(), names.end()).size(), 22u);
  EXPECT_EQ(names.front(), "ThumbRotate");
  EXPECT_EQ(names[10], "MiddleIndexAb");
  EXPECT_EQ(names[14], "RingMiddleAb");
  EXPECT_EQ(names.back(), "WristYaw");
}

TEST(CyberGloveSensors, IndexByName) {
  for (int i = 0; i < kCyberGloveSensorCount; ++i)
    EXPECT_EQ(cyberGloveSensorIndex(cyberGloveSensorNames()[static_cast<std::size_t>(i)]), i);
  EXPECT_EQ(cyberGloveSensorIndex("thumbrotate"), -1);
  EXPECT_EQ(cyberGloveSensorIndex(""), -1);
}

TEST(CyberGloveSensors, ListNamesEverySensor) {
  const std::string list(cyberGloveSensorList());
  for (const auto name : cyberGloveSensorNames()) EXPECT_NE(list.find(name), std::string::npos) << name;
}

}  // namespace
}  // namespace pmdplan
