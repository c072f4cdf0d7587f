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

std::vector<SkippablePair> findSkippablePairs(const RobotModel& model, const SkippablePairSettings& params) {
  const auto& links = model.links();
  const std::size_t n = links.size();
  std::vector<char> adjacent(n * n, 0);
  std::vector<std::size_t> touched(n * n, 0);
  for (std::size_t l = 0; l < n; ++l) {
    const int p = geometricParent(model, static_cast<int>(l));
    if (p >= 0) adjacent[l * n + static_cast<std::size_t>(p)] = adjacent[static_cast<std::size_t>(p) * n + l] = 1;
  }

  Task task;
  task.name = "self-collision sampling";
  task.robot = std::shared_ptr<const RobotModel>(&model, [](const RobotModel*) {});
  ExactCollisionChecker checker(task);
  const auto contacts = [&](const Configuration& q, std::vector<std::size_t>& counts) {
    for (const auto& [a, b] : checker.check(q).pairs) {
      const auto ia = static_cast<std::size_t>(model.linkIndex(a));
      const auto ib = static_cast<std::size_t>(model.linkIndex(b));
      ++counts[ia * n + ib];
      if (ia != ib) ++counts[ib * n + ia];
    }
  };
  std::vector<std::size_t> atHome(n * n, 0);
  if (params.home.size() > 0) contacts(params.home, atHome);
  RandomSource random(params.seed);
  Configuration q(model.dof());
  for (std::size_t s = 0; s < params.samples; ++s) {
    for (int i = 0; i < model.dof(); ++i) {
      const auto& j = model.activeJoints()[static_cast<std::size_t>(i)];
      q[i] = random.uniform(j.lower, j.upper);
    }
    contacts(q, touched);
  }

  std::vector<SkippablePair> pairs;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      if (links[a].collisionShapes.empty() || links[b].collisionShapes.empty()) continue;
      const std::size_t k = a * n + b;
      if (adjacent[k])
        pairs.push_back({links[a].name, links[b].name, "Adjacent"});
      else if (atHome[k] > 0)
        pairs.push_back({links[a].name, links[b].name, "Default"});
      else if (params.samples > 0 && touched[k] == params.samples)
        pairs.push_back({links[a].name, links[b].name, "Always"});
      else if (touched[k] == 0 && !onDifferentBranches(model, static_cast<int>(a), static_cast<int>(b)))
        pairs.push_back({links[a].name, links[b].name, "Never"});
    }
  return pairs;
}

std::string companionFileText(const RobotModel& model, const std::vector<SkippablePair>& pairs,
                              const std::string& generatedBy) {
  const int palm = model.palmLink();
  return companionFileText(model.name(), model.groupDefinitions(),
                           palm >= 0 ? model.links()[static_cast<std::size_t>(palm)].name : std::string(), pairs,
                           generatedBy);
}

std::string companionFileText(const std::string& robotName, const std::vector<RobotModel::GroupDefinition>& groups,
                              const std::string& palmLink, const std::vector<SkippablePair>& pairs,
                              const std::string& generatedBy) {
  // XML forbids "--" inside a comment (and a comment ending in "-").
  std::string comment = generatedBy;
  for (std::size_t at = comment.find("--"); at != std::string::npos; at = comment.find("--", at))
    comment.insert(at + 1, " ");
  if (!comment.empty() && comment.back() == '-') comment += ' ';
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<!-- Planning groups and self-collision pairs that may be skipped.\n     " << comment
      << " -->\n<robot name=\"" << robotName << "\">\n";
  for (const auto& [name, joints] : groups) {
    out << "  <group name=\"" << name << "\">\n";
    for (const auto& j : joints) out << "    <joint name=\"" << j << "\"/>\n";
    out << "  </group>\n";
  }
  const auto has = [&](const char* group) {
    return std::any_of(groups.begin(), groups.end(), [&](const auto& g) { return g.first == group; });
  };
  if (!palmLink.empty() && has("hand"))
    out << "  <end_effector name=\"hand\" parent_link=\"" << palmLink << "\" group=\"hand\""
        << (has("arm") ? " parent_group=\"arm\"" : "") << "/>\n";
  for (const auto& p : pairs)
    out << "  <disable_collisions link1=\"" << p.linkA << "\" link2=\"" << p.linkB << "\" reason=\"" << p.reason
        << "\"/>\n";
  out << "</robot>\n";
  return out.str();
}

}  // namespace pmdplan
