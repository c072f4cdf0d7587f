// Every object of the paper's tasks matters: without it, the PMD planner with the same seed plans
// differently (another path, roadmap or sample count) for some seed of 64, at the paper's neighbour
// radius (1 x d(c_ini, c_goal)); the count at twice that radius is printed beside it. An object that
// changes nothing makes the task easier than the paper's description says it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <set>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {
namespace {

// The objects of each scene, each the obstacles that make it up. The supports the objects stand on
// (the table, the floor) are left out.
struct SceneObjects {
  std::string task;
  std::vector<std::vector<std::string>> objects;
};

const std::vector<SceneObjects>& sceneObjects() {
  static const std::vector<SceneObjects> scenes = {
      {"can_on_table", {{"goal_can"}, {"obstacle_can"}}},
      {"cans_on_desk", {{"goal_can"}, {"obstacle_can"}, {"stacked_can"}}},
      {"can_in_box", {{"goal_can"}, {"box_wall_far"}, {"box_wall_near"}, {"box_wall_left"}, {"box_wall_right"}}},
      {"cans_in_shelf",
       {{"shelf_panel_left", "shelf_panel_right", "shelf_board_0", "shelf_board_1", "shelf_board_2", "shelf_board_3",
         "shelf_board_4"},
        {"right_can"},
        {"left_can"},
        {"t_stem", "t_bar"}}},
      {"t_in_clutter",
       {{"t_stem", "t_bar"},
        {"upright_book"},
        {"recycling_bin"},
        {"can"},
        {"mug", "mug_handle"},
        {"plastic_mug", "plastic_mug_handle"},
        {"lying_book"}}},
  };
  return scenes;
}

const std::set<std::string> kSupports = {"table", "floor"};

// Objects that on our model change no seeded plan over 64 seeds at either radius, each where the
// authors' problem files (or, for t_in_clutter, our reading of the paper's Fig. 16-4) place it: the
// pmd planner's samples never come near them. The published ones are not moved: nothing in the
// paper's text or figures says where else they would stand (docs/deviations.md, "Objects that do
// not matter", has the measurements). They are still planned without, and reported when they start
// to matter, so the list can shrink.
const std::set<std::string> kNotYetRelevant = {
    // published places; the straight segment touches only the T's stem, the goal hand is 32 mm
    // above the board the T stands on and the palm stays in front of the shelf
    "cans_in_shelf/"
    "shelf_panel_left+shelf_panel_right+shelf_board_0+shelf_board_1+shelf_board_2+shelf_board_3+shelf_board_4",
    "cans_in_shelf/right_can",      // published, beside the T: 20 mm from the goal palm
    "cans_in_shelf/left_can",       // published, beside the T
    "t_in_clutter/mug+mug_handle",  // our layout: elsewhere on the table
    "t_in_clutter/lying_book",      // our layout: 30 mm high, far below the passage
};

struct PlanOutcome {
  PlannerStatus status;
  std::vector<Configuration> path;
  std::size_t nodes, samples, armTrials;
  bool operator==(const PlanOutcome& o) const {
    return status == o.status && nodes == o.nodes && samples == o.samples && armTrials == o.armTrials &&
           path.size() == o.path.size() &&
           std::equal(path.begin(), path.end(), o.path.begin(), [](const auto& a, const auto& b) { return a == b; });
  }
};

PlanOutcome plan(const Task& task, const SynergyModel& model, std::uint64_t seed, double radius) {
  CollisionChecking checking(task, CheckerKind::Fast, 0.001);
  TaskPlanningSettings options;
  options.synergies = &model;
  options.parameters.seed = seed;
  options.parameters.neighbourThreshold = radius;
  options.parameters.timeLimit = 10.0;
  const TaskPlanningResult r = planTask(task, checking, options);
  return {r.status, r.path, r.statistics.roadmapNodes, r.statistics.samples, r.statistics.armTrials};
}

Task without(const Task& task, const std::vector<std::string>& names) {
  Task reduced = task;
  std::erase_if(reduced.obstacles, [&](const Obstacle& o) { return std::ranges::find(names, o.name) != names.end(); });
  EXPECT_EQ(reduced.obstacles.size() + names.size(), task.obstacles.size())
      << "a listed obstacle is not in " << task.name;
  return reduced;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : "+") + n;
  return text;
}

void PrintTo(const SceneObjects& scene, std::ostream* out) { *out << scene.task; }

class ObstacleRelevance : public ::testing::TestWithParam<SceneObjects> {};

TEST_P(ObstacleRelevance, EveryObstacleBesidesTheSupportsBelongsToAListedObject) {
  const Task task = loadTaskByName(GetParam().task);
  std::set<std::string> listed;
  for (const auto& object : GetParam().objects) listed.insert(object.begin(), object.end());
  for (const Obstacle& o : task.obstacles)
    EXPECT_TRUE(kSupports.count(o.name) || listed.count(o.name)) << o.name << " of " << task.name << " is not tested";
}

TEST_P(ObstacleRelevance, RemovingAnyObjectChangesASeededPlan) {
  const Task task = loadTaskByName(GetParam().task);
  const SynergyModel model = loadSynergyModel(defaultSynergyModelPath(task.robot->name()));
  // The paper's radius (1 × d(c_ini, c_goal)), asserted, and the wider one of earlier defaults.
  for (const double factor : {1.0, 2.0}) {
    std::vector<PlanOutcome> full;
    std::vector<std::uint64_t> seeds(64);
    std::iota(seeds.begin(), seeds.end(), 1);
    for (const std::uint64_t seed : seeds) full.push_back(plan(task, model, seed, factor));
    for (const auto& object : GetParam().objects) {
      const Task reduced = without(task, object);
      int changed = 0;
      for (std::size_t s = 0; s < seeds.size(); ++s) changed += !(plan(reduced, model, seeds[s], factor) == full[s]);
      const bool listed = kNotYetRelevant.count(task.name + "/" + joined(object)) > 0;
      if (!listed && factor == 1.0) {
        EXPECT_GT(changed, 0) << task.name << " without " << joined(object) << ", radius factor " << factor
                              << ": every seed plans as with it";
      }
      std::printf("%s without %s, radius factor %.0f: %d of %zu seeds change%s\n", task.name.c_str(),
                  joined(object).c_str(), factor, changed, seeds.size(),
                  listed ? (changed ? " (listed as not yet relevant: it now matters)" : " (not yet relevant)") : "");
    }
  }
}

INSTANTIATE_TEST_SUITE_P(PaperTasks, ObstacleRelevance, ::testing::ValuesIn(sceneObjects()),
                         [](const auto& info) { return info.param.task; });

}  // namespace
}  // namespace pmdplan
