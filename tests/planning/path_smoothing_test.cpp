#include "pmdplan/planning/path_smoothing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "pmdplan/core/random_source.hpp"

namespace pmdplan {
namespace {

PlanningSpace unitSquare() {
  PlanningSpace space;
  space.joints = {{"x", 0.0, 1.0}, {"y", 0.0, 1.0}};
  space.armIndices = {0};
  space.handIndices = {1};
  return space;
}

struct Box {
  double x0, y0, x1, y1;
};

/// Exact segment-versus-axis-aligned-box test (slab clipping).
bool segmentHitsBox(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Box& box) {
  double t0 = 0.0;
  double t1 = 1.0;
  const double lo[2] = {box.x0, box.y0};
  const double hi[2] = {box.x1, box.y1};
  for (int axis = 0; axis < 2; ++axis) {
    const double d = b[axis] - a[axis];
    if (d == 0.0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;
      continue;
    }
    double enter = (lo[axis] - a[axis]) / d;
    double leave = (hi[axis] - a[axis]) / d;
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    if (t0 > t1) return false;
  }
  return true;
}

class BoxesMotionValidator : public MotionValidator {
 public:
  std::vector<Box> boxes;
  std::size_t calls = 0;
  bool isValid(const Configuration& from, const Configuration& to) override {
    ++calls;
    return std::none_of(boxes.begin(), boxes.end(), [&](const Box& box) { return segmentHitsBox(from, to, box); });
  }
  std::size_t statesChecked() const override { return calls; }
};

TEST(PathSmoothing, AFreeDirectSegmentLeavesOnlyTheEnds) {
  const std::vector<Configuration> path = {Eigen::Vector2d(0.1, 0.1), Eigen::Vector2d(0.5, 0.9),
                                           Eigen::Vector2d(0.9, 0.1)};
  BoxesMotionValidator motion;
  const std::vector<Configuration> smoothed = smoothPath(path, unitSquare(), motion);
  ASSERT_EQ(smoothed.size(), 2u);
  EXPECT_EQ(smoothed.front(), path.front());
  EXPECT_EQ(smoothed.back(), path.back());
}

TEST(PathSmoothing, KeepsTheDetourAroundAnObstacle) {
  // Around a box in the middle: 0 -> 1 -> 2 -> 3 with 1 and 2 above it; 1 -> 3 and 0 -> 2 are free
  // only if they pass above the box, which 0 -> 2 does not.
  const std::vector<Configuration> path = {Eigen::Vector2d(0.0, 0.5), Eigen::Vector2d(0.3, 0.9),
                                           Eigen::Vector2d(0.7, 0.9), Eigen::Vector2d(1.0, 0.5)};
  BoxesMotionValidator motion;
  motion.boxes = {{0.25, 0.2, 0.75, 0.8}};
  const std::vector<std::size_t> kept = shortcutPathIndices(path, unitSquare(), motion);
  EXPECT_EQ(kept, (std::vector<std::size_t>{0, 1, 2, 3}));
}

TEST(PathSmoothing, TakesAShortcutThatSkipsNodes) {
  // A zig-zag in free space but for one box that only blocks the straight line 0 -> 4.
  const std::vector<Configuration> path = {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.2, 0.6),
                                           Eigen::Vector2d(0.4, 0.1), Eigen::Vector2d(0.6, 0.7),
                                           Eigen::Vector2d(1.0, 0.0)};
  BoxesMotionValidator motion;
  motion.boxes = {{0.45, -0.1, 0.55, 0.05}};
  const std::vector<Configuration> smoothed = smoothPath(path, unitSquare(), motion);
  EXPECT_LT(smoothed.size(), path.size());
  EXPECT_LT(pathLength(smoothed, unitSquare()), pathLength(path, unitSquare()));
  for (std::size_t i = 0; i + 1 < smoothed.size(); ++i) EXPECT_TRUE(motion.isValid(smoothed[i], smoothed[i + 1]));
}

// The property the planner relies on: over many random free paths among random boxes, smoothing
// never lengthens a path, keeps its ends, uses only the path's own nodes and only free segments.
TEST(PathSmoothing, NeverLengthensAPath) {
  const PlanningSpace space = unitSquare();
  RandomSource random(42);
  int shortened = 0;
  for (int trial = 0; trial < 300; ++trial) {
    BoxesMotionValidator motion;
    for (int b = 0; b < 4; ++b) {
      const double x = random.uniform01();
      const double y = random.uniform01();
      motion.boxes.push_back({x, y, x + 0.05 + 0.2 * random.uniform01(), y + 0.05 + 0.2 * random.uniform01()});
    }
    // A random walk whose every step is free (steps that collide are redrawn), from a start
    // outside every box (a zero-length segment is a point test).
    std::vector<Configuration> path;
    while (path.empty()) {
      const Eigen::Vector2d first(random.uniform01(), random.uniform01());
      if (motion.isValid(first, first)) path.push_back(first);
    }
    while (path.size() < 12) {
      const Eigen::Vector2d next(random.uniform01(), random.uniform01());
      if (motion.isValid(path.back(), next)) path.push_back(next);
    }
    const std::vector<std::size_t> kept = shortcutPathIndices(path, space, motion);
    std::vector<Configuration> smoothed;
    for (const std::size_t i : kept) smoothed.push_back(path[i]);
    ASSERT_GE(kept.size(), 2u);
    EXPECT_EQ(kept.front(), 0u);
    EXPECT_EQ(kept.back(), path.size() - 1);
    EXPECT_LE(pathLength(smoothed, space), pathLength(path, space)) << "trial " << trial;
    for (std::size_t i = 0; i + 1 < smoothed.size(); ++i)
      EXPECT_TRUE(motion.isValid(smoothed[i], smoothed[i + 1])) << "trial " << trial;
    if (pathLength(smoothed, space) < pathLength(path, space)) ++shortened;
  }
  EXPECT_GT(shortened, 150) << "random zig-zags should nearly always shorten";
}

TEST(PathSmoothing, ShortPathsAreReturnedAsTheyAre) {
  BoxesMotionValidator motion;
  const std::vector<Configuration> two = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)};
  EXPECT_EQ(smoothPath(two, unitSquare(), motion), two);
  EXPECT_EQ(motion.calls, 0u);
  EXPECT_TRUE(smoothPath({}, unitSquare(), motion).empty());
}

// Bounded work: a path of many nodes (a tiny planner step makes them) is smoothed in windows, each
// at most kMaxSmoothingWindowNodes nodes, so the tables never grow with the square of the path.
TEST(PathSmoothing, ALongPathIsSmoothedWindowByWindow) {
  const std::size_t n = 2 * kMaxSmoothingWindowNodes + 10;
  std::vector<Configuration> path;
  for (std::size_t i = 0; i < n; ++i)
    path.push_back(Eigen::Vector2d(0.05 + 0.9 * double(i) / double(n - 1), i % 2 == 0 ? 0.4 : 0.6));
  BoxesMotionValidator motion;  // no obstacle: each window collapses to its two ends
  const std::vector<std::size_t> kept = shortcutPathIndices(path, unitSquare(), motion);
  EXPECT_EQ(kept, (std::vector<std::size_t>{0, kMaxSmoothingWindowNodes - 1, 2 * kMaxSmoothingWindowNodes - 2, n - 1}));
}

// A stop (the run's deadline, Ctrl-C in Python) ends the smoothing at once with a path over the
// edges known to be free; before, it went on checking edges for as long as they took.
TEST(PathSmoothing, AStopKeepsOnlyEdgesAlreadyChecked) {
  const std::vector<Configuration> path = {Eigen::Vector2d(0.1, 0.1), Eigen::Vector2d(0.5, 0.9),
                                           Eigen::Vector2d(0.9, 0.1)};
  BoxesMotionValidator motion;
  EXPECT_EQ(shortcutPathIndices(path, unitSquare(), motion, [] { return true; }), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(motion.calls, 0u);
  EXPECT_EQ(shortcutPathIndices(path, unitSquare(), motion, [] { return false; }), (std::vector<std::size_t>{0, 2}));
}

}  // namespace
}  // namespace pmdplan
