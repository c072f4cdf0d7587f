#pragma once
// A task's robot and obstacles as the contact reference's solids (support/contact_reference.hpp),
// posed by the model's forward kinematics: the deepest penetration of a configuration over the
// pairs the checkers test (the enabled self pairs and every link against every obstacle), with
// the shapes named. Independent of both checkers' geometry: the URDF's shapes as written (a URDF
// capsule is its cylinder and two spheres).
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "support/contact_reference.hpp"

namespace pmdplan::testing {

struct ReferenceContact {
  double metres = 0.0;  ///< the reference's signed distance (negative: depth)
  std::string pair;     ///< "link - obstacle" or "link - link"
};

class ReferenceScene {
 public:
  /// `checker` supplies the kinematics and the enabled self pairs (outlives the scene).
  ReferenceScene(const Task& task, const ExactCollisionChecker& checker) : task_(task), checker_(checker) {
    for (const auto& link : task.robot->links()) {
      auto& shapes = links_.emplace_back();
      for (const auto& placed : link.collisionShapes) {
        World local{reference::solid(placed.shape, placed.pose), 0.0, kindName(placed.shape, shapes.size())};
        local.radius = bound(placed, local.solid);
        shapes.push_back(std::move(local));
      }
    }
    for (const auto& obstacle : task.obstacles) {
      World world{reference::solid(obstacle.shape, obstacle.pose), 0.0, kindName(obstacle.shape, 0)};
      world.radius = bound({obstacle.shape, obstacle.pose}, world.solid);
      obstacles_.push_back(std::move(world));
    }
  }

  /// The deepest pair penetrating by at least `depth` metres (the first found at that depth), or
  /// nullopt when no pair does.
  std::optional<ReferenceContact> penetration(const Configuration& q, double depth) {
    pose(q);
    std::optional<ReferenceContact> deepest;
    const auto consider = [&](const World& a, const World& b, const std::string& names) {
      // sd >= (centre distance - both bounds): skip pairs that cannot reach `depth`.
      if ((a.solid.pose.translation() - b.solid.pose.translation()).norm() - a.radius - b.radius > -depth) return;
      const double sd = reference::signedDistance(a.solid, b.solid, -depth);
      if (sd <= -depth && (!deepest || sd < deepest->metres)) deepest = ReferenceContact{sd, names};
    };
    forEachPair(consider);
    return deepest;
  }

  /// True when every pair is at least `margin` metres apart.
  bool clear(const Configuration& q, double margin) {
    pose(q);
    bool clear = true;
    forEachPair([&](const World& a, const World& b, const std::string&) {
      if (!clear) return;
      if ((a.solid.pose.translation() - b.solid.pose.translation()).norm() - a.radius - b.radius > margin) return;
      clear = reference::signedDistance(a.solid, b.solid, margin) > margin;
    });
    return clear;
  }

 private:
  struct World {
    reference::Solid solid;
    double radius;     ///< encloses the solid around its origin
    std::string kind;  ///< "box 2": its kind and index among its link's (or obstacle's) shapes
  };

  static std::string kindName(const Shape& shape, std::size_t index) {
    static const char* const kNames[] = {"box", "cylinder", "sphere", "mesh"};
    return std::string(kNames[shape.index()]) + " " + std::to_string(index);
  }

  static double bound(const PlacedShape& placed, const reference::Solid& solid) {
    if (!solid.vertices) return boundingRadius(placed.shape);
    double r = 0.0;
    for (const auto& v : *solid.vertices) r = std::max(r, v.norm());
    return r;
  }

  void pose(const Configuration& q) {
    checker_.kinematics().linkPoses(q, poses_);
    world_.assign(links_.size(), {});
    for (std::size_t l = 0; l < links_.size(); ++l)
      for (const auto& local : links_[l]) {
        World& w = world_[l].emplace_back(local);
        w.solid.pose = poses_[l] * local.solid.pose;
      }
  }

  template <typename Visit>
  void forEachPair(Visit&& visit) {
    const auto& names = task_.robot->links();
    for (auto [a, b] : checker_.selfPairs())
      for (const auto& sa : world_[static_cast<std::size_t>(a)])
        for (const auto& sb : world_[static_cast<std::size_t>(b)])
          visit(sa, sb,
                names[static_cast<std::size_t>(a)].name + " (" + sa.kind + ") - " +
                    names[static_cast<std::size_t>(b)].name + " (" + sb.kind + ")");
    for (std::size_t l = 0; l < world_.size(); ++l)
      for (std::size_t o = 0; o < obstacles_.size(); ++o)
        for (const auto& s : world_[l])
          visit(s, obstacles_[o],
                names[l].name + " (" + s.kind + ") - " + task_.obstacles[o].name + " (" + obstacles_[o].kind + ")");
  }

  const Task& task_;
  const ExactCollisionChecker& checker_;
  std::vector<std::vector<World>> links_;  ///< in the link frames
  std::vector<World> obstacles_;
  std::vector<std::vector<World>> world_;
  LinkPoses poses_;
};

}  // namespace pmdplan::testing
