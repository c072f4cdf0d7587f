#include "pmdplan/model/collision_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/mesh_file.hpp"

namespace pmdplan {
namespace {

std::string shown(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

/// A problem when `value` is not a finite number in [low, high].
std::optional<ShapeBoundsProblem> outside(double value, double low, double high, const std::string& part,
                                          const std::string& what) {
  if (std::isfinite(value) && value >= low && value <= high) return std::nullopt;
  return ShapeBoundsProblem{part, "expected " + what + ", a finite number from " + shown(low) + " to " + shown(high) +
                                      ", got " + shown(value)};
}

std::optional<ShapeBoundsProblem> length(double value, const std::string& part, const std::string& what) {
  return outside(value, ShapeBounds::kMinLength, ShapeBounds::kMaxLength, part, what + " in metres");
}

}  // namespace

std::optional<ShapeBoundsProblem> shapeBoundsProblem(const Shape& shape) {
  struct Visitor {
    std::optional<ShapeBoundsProblem> operator()(const BoxShape& b) const {
      for (int i = 0; i < 3; ++i)
        if (auto problem = length(b.size[i], ".box[" + std::to_string(i) + "]", "a box side")) return problem;
      return std::nullopt;
    }
    std::optional<ShapeBoundsProblem> operator()(const CylinderShape& c) const {
      if (auto problem = length(c.radius, ".cylinder.radius", "a radius")) return problem;
      return length(c.length, ".cylinder.length", "a length");
    }
    std::optional<ShapeBoundsProblem> operator()(const SphereShape& s) const {
      return length(s.radius, ".sphere", "a radius");
    }
    std::optional<ShapeBoundsProblem> operator()(const MeshShape& m) const {
      for (int i = 0; i < 3; ++i)
        if (auto problem = outside(m.scale[i], ShapeBounds::kMinMeshScale, ShapeBounds::kMaxMeshScale,
                                   ".mesh.scale[" + std::to_string(i) + "]", "a scale factor"))
          return problem;
      return std::nullopt;
    }
  };
  return std::visit(Visitor{}, shape);
}

std::optional<ShapeBoundsProblem> positionBoundsProblem(const Eigen::Vector3d& position) {
  for (int i = 0; i < 3; ++i)
    if (auto problem = outside(position[i], -ShapeBounds::kMaxPosition, ShapeBounds::kMaxPosition,
                               "[" + std::to_string(i) + "]", "a coordinate in metres"))
      return problem;
  return std::nullopt;
}

void checkShapeBounds(const Shape& shape, const std::string& file, const std::string& field) {
  if (auto problem = shapeBoundsProblem(shape)) throw InputError(file, field + problem->part, problem->message);
}

void checkPositionBounds(const Eigen::Vector3d& position, const std::string& file, const std::string& field) {
  if (auto problem = positionBoundsProblem(position)) throw InputError(file, field + problem->part, problem->message);
}

double boundingRadius(const Shape& shape) {
  struct Visitor {
    double operator()(const BoxShape& b) const { return 0.5 * b.size.norm(); }
    double operator()(const CylinderShape& c) const { return std::hypot(c.radius, 0.5 * c.length); }
    double operator()(const SphereShape& s) const { return s.radius; }
    double operator()(const MeshShape& m) const {
      if (!m.triangles) return std::numeric_limits<double>::infinity();
      double r = 0.0;
      for (const auto& v : m.triangles->vertices) r = std::max(r, v.norm());
      return r;
    }
  };
  return std::visit(Visitor{}, shape);
}

}  // namespace pmdplan
