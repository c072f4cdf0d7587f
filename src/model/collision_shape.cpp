#include "pmdplan/model/collision_shape.hpp"

#include <limits>

namespace pmdplan {

double boundingRadius(const Shape& shape) {
  struct Visitor {
    double operator()(const BoxShape& b) const { return 0.5 * b.size.norm(); }
    double operator()(const CylinderShape& c) const { return std::hypot(c.radius, 0.5 * c.length); }
    double operator()(const SphereShape& s) const { return s.radius; }
    double operator()(const MeshShape&) const { return std::numeric_limits<double>::infinity(); }
  };
  return std::visit(Visitor{}, shape);
}

}  // namespace pmdplan
