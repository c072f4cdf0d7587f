#include "urdf_reader.hpp"

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/mesh_file.hpp"
#include "pmdplan/model/resource_path.hpp"
#include "srdf_name_matching.hpp"
#include "urdf_checks.hpp"

namespace pmdplan {
namespace {

/// Joint limits, mimic multipliers and offsets beyond this (rad, m) are refused: larger values make
/// a segment's state count or normalised distances overflow.
constexpr double kMaxJointMagnitude = 1000.0;

/// urdfdom reports problems through console_bridge; keep the first error to put in our message
/// instead of letting it print to the terminal.
class CapturedUrdfErrors : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first.empty()) first = text;
  }
  std::string first;
};

Eigen::Isometry3d toIsometry(const urdf::Pose& pose) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  t.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  return t;
}

std::optional<Shape> toShape(const urdf::Geometry& geometry, const std::filesystem::path& urdf,
                             const std::string& field) {
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(geometry);
      return BoxShape{Eigen::Vector3d(b.dim.x, b.dim.y, b.dim.z)};
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(geometry);
      return CylinderShape{c.radius, c.length};
    }
    case urdf::Geometry::SPHERE:
      return SphereShape{static_cast<const urdf::Sphere&>(geometry).radius};
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(geometry);
      return loadMeshShape(resolveResourcePath(m.filename, urdf, field + ".mesh.filename"),
                           Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z));
    }
  }
  return std::nullopt;
}

bool hasGroupNamed(const RobotModel& model, const std::string& name) {
  return std::any_of(model.groupDefinitions().begin(), model.groupDefinitions().end(),
                     [&](const auto& g) { return g.first == name; });
}

/// A continuous joint's <limit> counts as a range when it gives lower < upper (urdfdom leaves both
/// 0 when only effort and velocity are written).
bool hasLimitRange(const urdf::JointLimitsSharedPtr& limits) {
  return limits && (limits->lower != 0.0 || limits->upper != 0.0);
}

}  // namespace

RobotModel RobotModelBuilder::build(const std::filesystem::path& urdf,
                                    const std::optional<std::filesystem::path>& srdf) {
  RobotModel model;
  model.urdfPath_ = urdf;
  readUrdf(model, urdf);
  resolveMimics(model);
  if (srdf) readSrdf(model, *srdf);
  assignActiveOrder(model);
  const std::size_t n = model.links_.size();
  model.disabledMatrix_.assign(n * n, 0);
  for (auto [a, b] : model.disabledPairs_) {
    model.disabledMatrix_[static_cast<std::size_t>(a) * n + static_cast<std::size_t>(b)] = 1;
    model.disabledMatrix_[static_cast<std::size_t>(b) * n + static_cast<std::size_t>(a)] = 1;
  }
  return model;
}

void RobotModelBuilder::readUrdf(RobotModel& model, const std::filesystem::path& urdf) {
  const std::string file = urdf.string();
  const std::string xml = readTextFile(urdf);
  // tinyxml2 first: it names the line of an XML syntax error, which urdfdom does not.
  tinyxml2::XMLDocument document;
  if (document.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(file, "line " + std::to_string(document.ErrorLineNum()),
                     std::string("malformed XML: ") + document.ErrorStr());
  if (!document.RootElement() || std::string(document.RootElement()->Name()) != "robot")
    throw InputError(file, "root element", "expected <robot>");
  urdf_checks::checkSize(document, file);
  urdf_checks::checkNoXacro(document, file);

  urdf::ModelInterfaceSharedPtr parsed;
  {
    static std::mutex consoleMutex;  // console_bridge's handler is process-global
    std::lock_guard lock(consoleMutex);
    CapturedUrdfErrors errors;
    console_bridge::useOutputHandler(&errors);
    parsed = urdf::parseURDF(xml);
    console_bridge::restorePreviousOutputHandler();
    if (!parsed)
      throw InputError(
          file, "robot",
          "not a valid URDF: " + (errors.first.empty() ? std::string("urdfdom rejected it") : errors.first));
  }
  model.name_ = parsed->getName();
  urdf_checks::checkTree(*parsed, file);
  urdf_checks::checkAllCollisionsRead(document, *parsed, file);

  // Links in a deterministic order: the tree from the root, children in joint-name order.
  std::map<std::string, int> linkIndex;
  MeshTriangleBudget meshBudget("collision meshes of the robot");
  std::function<void(const urdf::LinkConstSharedPtr&)> addLink = [&](const urdf::LinkConstSharedPtr& link) {
    Link out;
    out.name = link->name;
    for (std::size_t i = 0; i < link->collision_array.size(); ++i) {
      const auto& collision = link->collision_array[i];
      if (!collision->geometry) continue;
      const std::string field = "link[" + link->name + "].collision[" + std::to_string(i) + "]";
      urdf_checks::checkGeometry(*collision->geometry, file, field);
      urdf_checks::checkPose(collision->origin, file, field);
      if (auto shape = toShape(*collision->geometry, urdf, field)) {
        if (const auto* mesh = std::get_if<MeshShape>(&*shape)) meshBudget.add(*mesh, file, field + ".mesh");
        out.collisionShapes.push_back({*shape, toIsometry(collision->origin)});
      }
    }
    for (std::size_t i = 0; i < link->visual_array.size(); ++i) {
      const auto& visual = link->visual_array[i];
      if (!visual->geometry || visual->geometry->type != urdf::Geometry::MESH) continue;
      const std::string reference = static_cast<const urdf::Mesh&>(*visual->geometry).filename;
      VisualMesh mesh{reference, {}};
      try {
        mesh.file = resolveResourcePath(reference, urdf, "link[" + link->name + "].visual[" + std::to_string(i) + "]");
      } catch (const InputError&) {
        mesh.file.clear();
      }
      out.visualMeshes.push_back(std::move(mesh));
    }
    linkIndex[out.name] = static_cast<int>(model.links_.size());
    model.links_.push_back(std::move(out));
    std::vector<urdf::JointSharedPtr> children = link->child_joints;
    std::sort(children.begin(), children.end(), [](const auto& a, const auto& b) { return a->name < b->name; });
    for (const auto& joint : children) {
      const int parent = linkIndex.at(link->name);
      auto child = parsed->getLink(joint->child_link_name);
      Joint j;
      j.name = joint->name;
      j.parentLink = parent;
      j.origin = toIsometry(joint->parent_to_joint_origin_transform);
      const Eigen::Vector3d axis(joint->axis.x, joint->axis.y, joint->axis.z);
      const std::string field = "joint[" + joint->name + "]";
      urdf_checks::checkPose(joint->parent_to_joint_origin_transform, file, field);
      switch (joint->type) {
        case urdf::Joint::FIXED:
          j.type = JointType::Fixed;
          break;
        case urdf::Joint::REVOLUTE:
          j.type = JointType::Revolute;
          break;
        case urdf::Joint::CONTINUOUS:
          j.type = JointType::Continuous;
          break;
        case urdf::Joint::PRISMATIC:
          j.type = JointType::Prismatic;
          break;
        default:
          throw InputError(file, field, "joint type not supported (expected fixed, revolute, continuous or prismatic)");
      }
      if (j.type != JointType::Fixed) {
        if (!(axis.norm() > 1e-12) || !axis.allFinite())
          throw InputError(file, field + ".axis", "axis must be a non-zero vector");
        j.axis = axis.normalized();
        if (j.type == JointType::Continuous && !hasLimitRange(joint->limits)) {
          // No range given: one turn, without wrap-around (see docs/bring_your_own_robot.md).
          j.lower = -M_PI;
          j.upper = M_PI;
        } else {
          if (!joint->limits)
            throw InputError(file, field + ".limit", "revolute and prismatic joints need <limit lower upper>");
          j.lower = joint->limits->lower;
          j.upper = joint->limits->upper;
          j.velocity =
              std::isfinite(joint->limits->velocity) && joint->limits->velocity > 0.0 ? joint->limits->velocity : 0.0;
          if (!(std::abs(j.lower) <= kMaxJointMagnitude) || !(std::abs(j.upper) <= kMaxJointMagnitude) ||
              !(j.lower < j.upper))
            throw InputError(file, field + ".limit",
                             "expected lower < upper within +-1000 (rad or m), got " + std::to_string(j.lower) +
                                 " .. " + std::to_string(j.upper));
        }
      }
      const int jointIdx = static_cast<int>(model.joints_.size());
      model.joints_.push_back(j);
      model.jointOrder_.push_back(jointIdx);
      addLink(child);
      model.joints_[static_cast<std::size_t>(jointIdx)].childLink = linkIndex.at(child->name);
      model.links_[static_cast<std::size_t>(linkIndex.at(child->name))].parentJoint = jointIdx;
    }
  };
  addLink(parsed->getRoot());
  model.rootLink_ = 0;

  // Mimic sources by name, resolved after every joint is known.
  for (auto& j : model.joints_) {
    const auto source = parsed->getJoint(j.name);
    if (!source->mimic) continue;
    const std::string field = "joint[" + j.name + "].mimic";
    const int src = model.jointIndex(source->mimic->joint_name);
    if (src < 0) throw InputError(file, field, "mimics unknown joint '" + source->mimic->joint_name + "'");
    if (j.type == JointType::Fixed) throw InputError(file, field, "a fixed joint cannot mimic another joint");
    j.mimicSource = src;
    j.mimicMultiplier = source->mimic->multiplier;
    j.mimicOffset = source->mimic->offset;
    if (!(std::abs(j.mimicMultiplier) <= kMaxJointMagnitude) || !(std::abs(j.mimicOffset) <= kMaxJointMagnitude))
      throw InputError(file, field, "multiplier and offset must be finite numbers within +-1000");
  }
}

void RobotModelBuilder::resolveMimics(RobotModel& model) {
  // A mimic chain must end at an independent joint; follow each one, at most one step per joint.
  const std::string file = model.urdfPath_.string();
  for (const auto& start : model.joints_) {
    if (start.mimicSource < 0) continue;
    int current = start.mimicSource;
    std::size_t steps = 0;
    while (model.joints_[static_cast<std::size_t>(current)].mimicSource >= 0) {
      current = model.joints_[static_cast<std::size_t>(current)].mimicSource;
      if (++steps > model.joints_.size())
        throw InputError(file, "joint[" + start.name + "].mimic",
                         "mimic cycle: the chain of mimicked joints never reaches an independent joint");
    }
  }
  // Flatten chains (a mimics b mimics c) so every mimic refers to an independent joint.
  for (auto& j : model.joints_) {
    while (j.mimicSource >= 0 && model.joints_[static_cast<std::size_t>(j.mimicSource)].mimicSource >= 0) {
      const Joint& mid = model.joints_[static_cast<std::size_t>(j.mimicSource)];
      j.mimicOffset += j.mimicMultiplier * mid.mimicOffset;
      j.mimicMultiplier *= mid.mimicMultiplier;
      j.mimicSource = mid.mimicSource;
    }
  }
}

void RobotModelBuilder::readSrdf(RobotModel& model, const std::filesystem::path& srdf) {
  const std::string file = srdf.string();
  const std::string xml = readTextFile(srdf);
  tinyxml2::XMLDocument document;
  if (document.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(file, "line " + std::to_string(document.ErrorLineNum()),
                     std::string("malformed XML: ") + document.ErrorStr());
  const auto* root = document.RootElement();
  if (!root || std::string(root->Name()) != "robot") throw InputError(file, "root element", "expected <robot>");
  const auto line = [](const tinyxml2::XMLElement* e) { return "line " + std::to_string(e->GetLineNum()); };
  std::vector<std::string> jointNames, linkNames;
  for (const auto& j : model.joints_) jointNames.push_back(j.name);
  for (const auto& l : model.links_) linkNames.push_back(l.name);
  const auto matched = [&](const std::vector<std::string>& names, const char* kind, const char* written,
                           const tinyxml2::XMLElement* at, const std::string& where) {
    const std::string name = written ? written : "";
    const SrdfNameMatch match = matchSrdfName(names, name);
    if (match.index < 0) throw InputError(file, line(at), where + unmatchedSrdfName(match, kind, name));
    return match.index;
  };
  for (const auto* group = root->FirstChildElement("group"); group; group = group->NextSiblingElement("group")) {
    const char* name = group->Attribute("name");
    if (!name) throw InputError(file, line(group), "<group> needs a name");
    const std::string where = std::string("group '") + name + "': ";
    std::vector<int> jointIndices;  // joints(), converted to active indices once the order is known
    const auto add = [&](int joint) {
      if (std::find(jointIndices.begin(), jointIndices.end(), joint) == jointIndices.end())
        jointIndices.push_back(joint);
    };
    // MoveIt's members, in document order: joints, links (their parent joints), chains, subgroups.
    for (const auto* member = group->FirstChildElement(); member; member = member->NextSiblingElement()) {
      const std::string kind = member->Name();
      if (kind == "joint") {
        add(matched(jointNames, "joint", member->Attribute("name"), member, where));
      } else if (kind == "link") {
        const int link = matched(linkNames, "link", member->Attribute("name"), member, where);
        if (const int joint = model.links_[static_cast<std::size_t>(link)].parentJoint; joint >= 0) add(joint);
      } else if (kind == "chain") {
        const int base =
            matched(linkNames, "link", member->Attribute("base_link"), member, where + "chain base_link: ");
        const int tip = matched(linkNames, "link", member->Attribute("tip_link"), member, where + "chain tip_link: ");
        std::vector<int> chain;
        for (int link = tip; link != base;) {
          const int joint = model.links_[static_cast<std::size_t>(link)].parentJoint;
          if (joint < 0)
            throw InputError(file, line(member),
                             where + "chain: link '" + linkNames[static_cast<std::size_t>(base)] +
                                 "' is not an ancestor of '" + linkNames[static_cast<std::size_t>(tip)] + "'");
          chain.push_back(joint);
          link = model.joints_[static_cast<std::size_t>(joint)].parentLink;
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) add(*it);
      } else if (kind == "group") {
        const char* sub = member->Attribute("name");
        const auto found = std::find_if(model.groups_.begin(), model.groups_.end(),
                                        [&](const auto& g) { return sub && g.first == sub; });
        if (found == model.groups_.end())
          throw InputError(file, line(member), where + "subgroup '" + (sub ? sub : "") + "' is not defined before it");
        for (const int joint : found->second) add(joint);
      }
    }
    std::vector<std::string> memberNames;
    for (const int joint : jointIndices) memberNames.push_back(jointNames[static_cast<std::size_t>(joint)]);
    model.groups_.emplace_back(name, std::move(jointIndices));
    model.groupDefinitions_.emplace_back(name, std::move(memberNames));
  }
  for (const auto* d = root->FirstChildElement("disable_collisions"); d;
       d = d->NextSiblingElement("disable_collisions")) {
    const int ia = matched(linkNames, "link", d->Attribute("link1"), d, "disable_collisions link1: ");
    const int ib = matched(linkNames, "link", d->Attribute("link2"), d, "disable_collisions link2: ");
    model.disabledPairs_.emplace_back(std::min(ia, ib), std::max(ia, ib));
  }
  if (const auto* ee = root->FirstChildElement("end_effector")) {
    model.palmLink_ = matched(linkNames, "link", ee->Attribute("parent_link"), ee, "end_effector parent_link: ");
    // A MoveIt SRDF names its groups freely (panda_arm, hand): the end effector says which is which.
    const auto alias = [&](const char* role, const char* attribute) {
      const char* groupName = ee->Attribute(attribute);
      if (!groupName || hasGroupNamed(model, role)) return;
      for (std::size_t g = 0; g < model.groups_.size(); ++g)
        if (model.groups_[g].first == groupName) {
          auto joints = model.groups_[g].second;
          auto names = model.groupDefinitions_[g].second;
          model.groups_.emplace_back(role, std::move(joints));
          model.groupDefinitions_.emplace_back(role, std::move(names));
          return;
        }
    };
    alias("hand", "group");
    alias("arm", "parent_group");
  }
  std::sort(model.disabledPairs_.begin(), model.disabledPairs_.end());
  model.disabledPairs_.erase(std::unique(model.disabledPairs_.begin(), model.disabledPairs_.end()),
                             model.disabledPairs_.end());
}

void RobotModelBuilder::reassignActiveOrder(RobotModel& model) {
  model.activeJoints_.clear();
  for (auto& joint : model.joints_) joint.activeIndex = -1;
  for (std::size_t g = 0; g < model.groups_.size(); ++g) {
    std::vector<int> jointIndices;
    for (const auto& name : model.groupDefinitions_[g].second) jointIndices.push_back(model.jointIndex(name));
    model.groups_[g].second = std::move(jointIndices);
  }
  assignActiveOrder(model);
}

void RobotModelBuilder::assignActiveOrder(RobotModel& model) {
  // Configuration layout: the groups' independent joints in the companion file's order (arm, then
  // hand), then any other independent joint in tree order.
  std::vector<int> order;
  const auto independent = [&](int j) {
    const Joint& joint = model.joints_[static_cast<std::size_t>(j)];
    return joint.type != JointType::Fixed && joint.mimicSource < 0;
  };
  for (const auto& [name, joints] : model.groups_)
    for (int j : joints)
      if (independent(j) && std::find(order.begin(), order.end(), j) == order.end()) order.push_back(j);
  for (int j : model.jointOrder_)
    if (independent(j) && std::find(order.begin(), order.end(), j) == order.end()) order.push_back(j);
  for (std::size_t i = 0; i < order.size(); ++i) {
    Joint& joint = model.joints_[static_cast<std::size_t>(order[i])];
    joint.activeIndex = static_cast<int>(i);
    model.activeJoints_.push_back({joint.name, joint.lower, joint.upper});
  }
  if (model.palmLink_ < 0)
    for (const auto& [name, joints] : model.groups_)
      if (name == "hand" && !joints.empty())
        model.palmLink_ = model.joints_[static_cast<std::size_t>(joints.front())].parentLink;
  // Groups hold active indices (mimic and fixed joints named in a group are dropped).
  for (auto& [name, joints] : model.groups_) {
    std::vector<int> active;
    for (int j : joints)
      if (const int a = model.joints_[static_cast<std::size_t>(j)].activeIndex; a >= 0) active.push_back(a);
    joints = std::move(active);
  }
}

}  // namespace pmdplan
