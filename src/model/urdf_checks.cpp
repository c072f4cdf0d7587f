#include "urdf_checks.hpp"

#include <cmath>
#include <map>
#include <vector>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/model/collision_shape.hpp"

namespace pmdplan::urdf_checks {
namespace {

/// urdfdom links children by shared_ptr: a loop is a reference cycle that would outlive the
/// model. Cut the links' child lists before refusing it.
[[noreturn]] void failTree(const urdf::ModelInterface& model, const std::string& file, const std::string& field,
                           const std::string& message) {
  for (const auto& [name, link] : model.links_) {
    link->child_links.clear();
    link->child_joints.clear();
  }
  throw InputError(file, field, message);
}

}  // namespace

void checkSize(const tinyxml2::XMLDocument& document, const std::string& file) {
  const tinyxml2::XMLElement* root = document.RootElement();
  if (!root) return;
  for (const char* kind : {"link", "joint"}) {
    int count = 0;
    for (const auto* e = root->FirstChildElement(kind); e; e = e->NextSiblingElement(kind))
      if (++count > kMaxLinks)
        throw InputError(file, std::string("<") + kind + ">",
                         "more than " + std::to_string(kMaxLinks) + " " + kind + "s, the most pmdplan reads");
  }
}

void checkTree(const urdf::ModelInterface& model, const std::string& file) {
  std::map<std::string, std::string> parentJoint;
  for (const auto& [name, joint] : model.joints_) {
    const std::string field = "joint[" + name + "]";
    if (joint->parent_link_name == joint->child_link_name)
      failTree(model, file, field, "its parent and child are the same link '" + joint->child_link_name + "'");
    const auto [previous, inserted] = parentJoint.emplace(joint->child_link_name, name);
    if (!inserted)
      failTree(model, file, field,
               "link '" + joint->child_link_name + "' already has the parent joint '" + previous->second +
                   "'; a URDF is a tree: one parent per link, no kinematic loops");
  }
  // Every link must be reached from the root by following child joints (a loop detached from the
  // root has a parent everywhere and would otherwise be dropped silently).
  const auto root = model.getRoot();
  if (!root) failTree(model, file, "robot", "no root link");
  std::map<std::string, bool> reached{{root->name, true}};
  std::vector<urdf::LinkConstSharedPtr> pending{root};
  while (!pending.empty()) {
    const auto link = pending.back();
    pending.pop_back();
    for (const auto& child : link->child_links)
      if (child && reached.emplace(child->name, true).second) pending.push_back(child);
  }
  for (const auto& [name, link] : model.links_)
    if (!reached.count(name))
      failTree(model, file, "link[" + name + "]",
               "not connected to the root link '" + root->name + "' (a kinematic loop or a second tree)");
}

void checkAllCollisionsRead(const tinyxml2::XMLDocument& document, const urdf::ModelInterface& model,
                            const std::string& file) {
  const tinyxml2::XMLElement* root = document.RootElement();
  for (const auto* e = root ? root->FirstChildElement("link") : nullptr; e; e = e->NextSiblingElement("link")) {
    const char* name = e->Attribute("name");
    const auto link = name ? model.getLink(name) : nullptr;
    if (!link) continue;
    std::size_t written = 0;
    for (const auto* c = e->FirstChildElement("collision"); c; c = c->NextSiblingElement("collision")) ++written;
    if (link->collision_array.size() != written)
      throw InputError(file, "link[" + link->name + "].collision (line " + std::to_string(e->GetLineNum()) + ")",
                       "a collision element could not be read; sizes and origins must be finite numbers");
  }
}

void checkNoXacro(const tinyxml2::XMLDocument& document, const std::string& file) {
  std::vector<const tinyxml2::XMLElement*> pending;
  if (document.RootElement()) pending.push_back(document.RootElement());
  while (!pending.empty()) {
    const tinyxml2::XMLElement* element = pending.back();
    pending.pop_back();
    const std::string where = "line " + std::to_string(element->GetLineNum());
    const std::string name = element->Name();
    if (name.rfind("xacro:", 0) == 0)
      throw InputError(file, where,
                       "<" + fieldKeyText(name) +
                           "> is a xacro element, which a URDF reader ignores: run xacro first "
                           "(xacro robot.urdf.xacro > robot.urdf) and give pmdplan its output");
    for (const auto* a = element->FirstAttribute(); a; a = a->Next()) {
      const std::string value = a->Value();
      if (value.find("${") != std::string::npos || value.find("$(") != std::string::npos)
        throw InputError(file, where + ", <" + fieldKeyText(name) + " " + fieldKeyText(a->Name()) + ">",
                         "holds a xacro substitution (${...} or $(...)), which a URDF reader does not expand: run "
                         "xacro first (xacro robot.urdf.xacro > robot.urdf) and give pmdplan its output");
    }
    for (const auto* child = element->FirstChildElement(); child; child = child->NextSiblingElement())
      pending.push_back(child);
  }
}

void checkGeometry(const urdf::Geometry& geometry, const std::string& file, const std::string& field) {
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(geometry);
      checkShapeBounds(BoxShape{Eigen::Vector3d(b.dim.x, b.dim.y, b.dim.z)}, file, field);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(geometry);
      checkShapeBounds(CylinderShape{c.radius, c.length}, file, field);
      break;
    }
    case urdf::Geometry::SPHERE:
      checkShapeBounds(SphereShape{static_cast<const urdf::Sphere&>(geometry).radius}, file, field);
      break;
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(geometry);
      checkShapeBounds(MeshShape{m.filename, Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z), nullptr}, file, field);
      break;
    }
  }
}

void checkPose(const urdf::Pose& pose, const std::string& file, const std::string& field) {
  const double rotation[] = {pose.rotation.x, pose.rotation.y, pose.rotation.z, pose.rotation.w};
  for (const double v : rotation)
    if (!std::isfinite(v)) throw InputError(file, field + ".origin", "xyz and rpy must be finite numbers");
  checkPositionBounds(Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z), file, field + ".origin.xyz");
}

}  // namespace pmdplan::urdf_checks
