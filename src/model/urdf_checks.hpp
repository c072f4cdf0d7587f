#pragma once
// Internal: what a URDF must satisfy before the reader walks it — a bounded size, a tree (one
// parent per link, no joint from a link to itself, every link reachable from the root) and finite,
// positive geometry within the shape bounds, no xacro left — so that no file can make the reader recurse without end or
// build a shape that never collides. Each check throws InputError naming the file and the link or joint.
#include <tinyxml2.h>
#include <urdf_model/model.h>

#include <string>

namespace pmdplan::urdf_checks {

/// The most <link> (and <joint>) elements a URDF may have; real hand-arm systems have ~50.
inline constexpr int kMaxLinks = 500;

/// At most kMaxLinks links and joints in the document.
void checkSize(const tinyxml2::XMLDocument& document, const std::string& file);

/// One parent joint per link, no joint whose parent is its child, every link below the root.
void checkTree(const urdf::ModelInterface& model, const std::string& file);

/// Every <collision> element of the document was read: urdfdom drops one whose numbers it cannot
/// parse ("nan", "inf", 1e400) without a word, which would leave a link that never collides.
void checkAllCollisionsRead(const tinyxml2::XMLDocument& document, const urdf::ModelInterface& model,
                            const std::string& file);

/// The URDF was run through xacro: no `xacro:` element and no `${...}` or `$(...)` substitution in
/// an attribute (urdfdom ignores both, which would read another robot than the one written).
void checkNoXacro(const tinyxml2::XMLDocument& document, const std::string& file);

/// A primitive or a mesh scale within ShapeBounds (model/collision_shape.hpp).
void checkGeometry(const urdf::Geometry& geometry, const std::string& file, const std::string& field);

/// A finite origin: a position within ShapeBounds::kMaxPosition and a finite rotation.
void checkPose(const urdf::Pose& pose, const std::string& file, const std::string& field);

}  // namespace pmdplan::urdf_checks
