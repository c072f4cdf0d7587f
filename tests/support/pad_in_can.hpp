#pragma once
// A configuration within 0.03 rad of can_on_table's goal in every joint (the thumb base at its
// limit, as in the goal) where the ring finger's distal pad box is 2.2 mm inside the goal can, and
// nothing else touches: FCL 0.7's box-cylinder test calls it free (issue 37). The tests use it as a goal (with no
// target, so the contact counts) and as a point of a path.
#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace pmdplan::test {

/// can_on_table's active joints in configuration order, and the configuration (radians).
inline const std::array<const char*, 19> kPadInCanJoints = {
    "tx90_joint_1",    "tx90_joint_2",   "tx90_joint_3",    "tx90_joint_4",     "tx90_joint_5",
    "tx90_joint_6",    "thumb_base",     "thumb_abduction", "thumb_proximal",   "thumb_medium",
    "index_abduction", "index_proximal", "index_medium",    "middle_abduction", "middle_proximal",
    "middle_medium",   "ring_abduction", "ring_proximal",   "ring_medium"};
inline const std::array<double, 19> kPadInCan = {
    -1.4295982437839614,   0.53701512130736606,  1.596734120817108,    -0.14590966938403382,  -0.50885774022700703,
    1.5759716244817537,    1.5707963267948966,   0.056674839118526811, -0.043732309746470584, 0.61804466724785145,
    -0.029375331060042316, 0.32859321474041819,  0.51473317834400611,  0.014878100431657583,  0.40289355902623025,
    0.6136972393938529,    0.018330785110474389, 0.48821579640333235,  0.48784837152732385};

/// The built-in can_on_table (its text from `scenes`/can_on_table.yaml) without its target and
/// with the pad-in-can configuration as its goal.
inline std::string padInCanTaskText(const std::filesystem::path& scenes) {
  std::ifstream in(scenes / "can_on_table.yaml");
  std::ostringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const auto target = yaml.find("\ntarget: goal_can\n");
  yaml.erase(target, std::string("\ntarget: goal_can").size());
  const auto goal = yaml.find("\ngoal:\n");
  auto end = yaml.find("\n", goal + 7);
  while (end != std::string::npos && yaml.compare(end, 3, "\n  ") == 0) end = yaml.find("\n", end + 1);
  std::ostringstream replaced;
  replaced.precision(17);
  replaced << "\ngoal:\n  joints:\n";
  for (std::size_t i = 0; i < kPadInCan.size(); ++i)
    replaced << "    " << kPadInCanJoints[i] << ": " << kPadInCan[i] << "\n";
  std::string goalText = replaced.str();
  goalText.pop_back();
  yaml.replace(goal, (end == std::string::npos ? yaml.size() : end) - goal, goalText);
  return yaml;
}

}  // namespace pmdplan::test
