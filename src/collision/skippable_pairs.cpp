#include "pmdplan/collision/skippable_pairs.hpp"

#include <algorithm>
#include <sstream>

#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/core/random_source.hpp"

namespace pmdplan {
namespace {

int parentLink(const RobotModel& model, int link) {
  const int joint = model.links()[static_cast<std::size_t>(link)].parentJoint;
  return joint < 0 ? -1 : model.joints()[static_cast<std::size_t>(joint)].parentLink;
}

std::vector<int> ancestry(const RobotModel& model, int link) {
  std::vector<int> chain;
  for (int l = link; l >= 0; l = parentLink(model, l)) chain.push_back(l);
  std::reverse(chain.begin(), chain.end());  // root first
  return chain;
}

/// Parent with geometry: links without geometry are looked through.
int geometricParent(const RobotModel& model, int link) {
  int p = parentLink(model, link);
  while (p >= 0 && model.links()[static_cast<std::size_t>(p)].collisionShapes.empty()) p = parentLink(model, p);
  return p;
}

}  // namespace

bool onDifferentBranches(const RobotModel& model, int linkA, int linkB) {
  const auto a = ancestry(model, linkA);
  const auto b = ancestry(model, linkB);
  std::size_t common = 0;
  while (common < a.size() && common < b.size() && a[common] == b[common]) ++common;
  // Neither is an ancestor of the other: they sit on different branches.
  return common < a.size() && common < b.size();
}

std::vector<SkippablePair> findSkippablePairs(const RobotModel& model, const SkippablePairParams& params) {
  const auto& links = model.links();
  const std::size_t n = links.size();
  std::vector<char> adjacent(n * n, 0), touched(n * n, 0);
  for (std::size_t l = 0; l < n; ++l) {
    const int p = geometricParent(model, static_cast<int>(l));
    if (p >= 0) adjacent[l * n + static_cast<std::size_t>(p)] = adjacent[static_cast<std::size_t>(p) * n + l] = 1;
  }

  Task task;
  task.name = "self-collision sampling";
  task.robot = std::shared_ptr<const RobotModel>(&model, [](const RobotModel*) {});
  ExactCollisionChecker checker(task);
  RandomSource random(params.seed);
  Configuration q(model.dof());
  for (std::size_t s = 0; s < params.samples; ++s) {
    for (int i = 0; i < model.dof(); ++i) {
      const auto& j = model.activeJoints()[static_cast<std::size_t>(i)];
      q[i] = random.uniform(j.lower, j.upper);
    }
    for (const auto& [a, b] : checker.check(q).pairs) {
      const auto ia = static_cast<std::size_t>(model.linkIndex(a));
      const auto ib = static_cast<std::size_t>(model.linkIndex(b));
      touched[ia * n + ib] = touched[ib * n + ia] = 1;
    }
  }

  std::vector<SkippablePair> pairs;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      if (links[a].collisionShapes.empty() || links[b].collisionShapes.empty()) continue;
      if (adjacent[a * n + b])
        pairs.push_back({links[a].name, links[b].name, "Adjacent"});
      else if (!touched[a * n + b] && !onDifferentBranches(model, static_cast<int>(a), static_cast<int>(b)))
        pairs.push_back({links[a].name, links[b].name, "Never"});
    }
  return pairs;
}

std::string companionFileText(const RobotModel& model, const std::vector<SkippablePair>& pairs, const std::string& generatedBy) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<!-- Planning groups and self-collision pairs that may be skipped.\n     "
      << generatedBy << " -->\n<robot name=\"" << model.name() << "\">\n";
  for (const auto& [name, joints] : model.groupDefinitions()) {
    out << "  <group name=\"" << name << "\">\n";
    for (const auto& j : joints) out << "    <joint name=\"" << j << "\"/>\n";
    out << "  </group>\n";
  }
  if (model.palmLink() >= 0)
    out << "  <end_effector name=\"hand\" parent_link=\"" << model.links()[static_cast<std::size_t>(model.palmLink())].name
        << "\" group=\"hand\"/>\n";
  for (const auto& p : pairs)
    out << "  <disable_collisions link1=\"" << p.linkA << "\" link2=\"" << p.linkB << "\" reason=\"" << p.reason << "\"/>\n";
  out << "</robot>\n";
  return out.str();
}

}  // namespace pmdplan
