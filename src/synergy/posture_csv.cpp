#include "pmdplan/synergy/posture_csv.hpp"

#include <algorithm>
#include <numbers>
#include <sstream>
#include <vector>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/text/csv_reading.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) {
    const auto first = cell.find_first_not_of(" \t\r");
    const auto last = cell.find_last_not_of(" \t\r");
    out.push_back(first == std::string::npos ? std::string() : cell.substr(first, last - first + 1));
  }
  return out;
}

std::string jointList(const JointLimits& hand) {
  std::string text;
  for (const auto& joint : hand) text += (text.empty() ? "" : ",") + joint.name;
  return text;
}

}  // namespace

Eigen::MatrixXd readPostureCsv(const std::filesystem::path& file, const JointLimits& hand, PostureUnit unit) {
  const std::string name = file.string();
  std::stringstream in(std::string(withoutByteOrderMark(readTextFile(file))));
  const double scale = unit == PostureUnit::Degrees ? std::numbers::pi / 180.0 : 1.0;
  const std::string unitName = unit == PostureUnit::Degrees ? "deg" : "rad";
  std::vector<int> columnJoint;  // hand index of each column
  std::vector<Eigen::VectorXd> rows;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = "line " + std::to_string(number);
    if (line.find_first_not_of(" \t\r") == std::string::npos || line.front() == '#') continue;
    const auto values = cells(line);
    if (columnJoint.empty()) {
      for (const auto& column : values) {
        const auto found =
            std::find_if(hand.begin(), hand.end(), [&](const JointLimit& j) { return j.name == column; });
        if (found == hand.end())
          throw InputError(name, where,
                           "header column " + quotedText(column) +
                               " is not a hand joint; expected a header naming the hand joints: " + jointList(hand));
        const int index = static_cast<int>(found - hand.begin());
        if (std::find(columnJoint.begin(), columnJoint.end(), index) != columnJoint.end())
          throw InputError(name, where, "header names '" + column + "' twice");
        columnJoint.push_back(index);
      }
      for (std::size_t j = 0; j < hand.size(); ++j)
        if (std::find(columnJoint.begin(), columnJoint.end(), static_cast<int>(j)) == columnJoint.end())
          throw InputError(name, where,
                           "no column for hand joint '" + hand[j].name +
                               "'; expected a header naming the hand joints: " + jointList(hand));
      continue;
    }
    if (values.size() != columnJoint.size())
      throw InputError(
          name, where,
          "expected " + std::to_string(columnJoint.size()) + " values, got " + std::to_string(values.size()));
    Eigen::VectorXd posture(static_cast<Eigen::Index>(hand.size()));
    for (std::size_t c = 0; c < values.size(); ++c) {
      const JointLimit& joint = hand[static_cast<std::size_t>(columnJoint[c])];
      const std::string field = where + ", column " + joint.name;
      const auto value = parseFiniteNumber(values[c]);
      if (!value) throw InputError(name, field, "expected a number in " + unitName + ", got " + quotedText(values[c]));
      const double radians = *value * scale;
      if (radians < joint.lower - 1e-9 || radians > joint.upper + 1e-9)
        throw InputError(name, field,
                         messageNumberText(*value) + " " + unitName + " is outside the joint limits " +
                             messageNumberText(joint.lower / scale) + " .. " + messageNumberText(joint.upper / scale) +
                             " " + unitName);
      posture[columnJoint[c]] = std::clamp(radians, joint.lower, joint.upper);
    }
    rows.push_back(std::move(posture));
  }
  if (columnJoint.empty())
    throw InputError(name, "line 1", "empty file; expected a header naming the hand joints: " + jointList(hand));
  Eigen::MatrixXd postures(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(hand.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) postures.row(static_cast<Eigen::Index>(r)) = rows[r].transpose();
  return postures;
}

}  // namespace pmdplan
