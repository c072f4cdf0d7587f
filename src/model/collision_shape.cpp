#include "pmdplan/model/collision_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pmdplan/model/mesh_file.hpp"

namespace pmdplan {

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
