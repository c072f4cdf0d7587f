#pragma once
// The path file: a planned path as JSON, with what produced it.
//
//   {
//     "task": "can_on_table",
//     "planner": "pmd",
//     "seed": 1,
//     "joint_names": ["a1", ...],                 active joints, configuration order
//     "points": [{"positions": [0.1, ...]}, ...], radians (metres for prismatic joints)
//     "phases": {"approach": [0, k], "closing": [k, n - 1]},  only for a grasp goal: point indices
//     "mimic": {"index_distal": ["index_medium", 1, 0], ...},  joint -> [source, multiplier, offset]
//     "statistics": {...}                          see statistics_json.hpp
//   }
//
// Numbers are written in their shortest exact form and keys in a fixed order, so the same path
// always gives the same bytes. Wall-clock times are left out unless asked for, so the same task
// and seed give a byte-identical file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

/// A coupled joint: value = multiplier · value(source) + offset.
struct MimicRelation {
  std::string joint;
  std::string source;
  double multiplier = 1.0;
  double offset = 0.0;

  bool operator==(const MimicRelation&) const = default;
};

struct PathFile {
  std::string task;
  std::string planner;
  std::uint64_t seed = 0;
  std::vector<std::string> jointNames;
  std::vector<Configuration> points;
  /// A grasp path's phases (docs/grasp_goals.md): the approach is points 0..k, the closing k..n-1,
  /// with k = closingFrom (the pre-grasp). Absent when the goal touches nothing.
  std::optional<std::size_t> closingFrom;
  std::vector<MimicRelation> mimic;
  PlanningStatistics statistics;
};

struct PathFileSettings {
  /// Also write planning_time_s and smoothing_time_s (makes the file differ from run to run).
  bool includeTimings = false;
};

/// The file's text. Throws std::invalid_argument for a point whose size differs from the joint
/// count or a value that is not finite (nothing JSON could hold).
std::string formatPathFile(const PathFile& path, const PathFileSettings& options = {});

/// formatPathFile written atomically (a reader never sees half a file).
void writePathFile(const std::filesystem::path& file, const PathFile& path, const PathFileSettings& options = {});

/// Reads and checks a path file. Every problem is an InputError naming `file` and the key
/// ("points[3].positions", "statistics.samples", ...): not JSON, unknown or missing keys, wrong
/// types, fewer than two points, a point with the wrong number of positions, duplicate joints,
/// phases that do not split the points into an approach and a closing of at least one segment each.
PathFile parsePathFile(const std::string& text, const std::string& file);
PathFile readPathFile(const std::filesystem::path& file);

}  // namespace pmdplan
