#pragma once
// Internal: FCL collision geometry for our shapes.
#include <fcl/fcl.h>

#include <memory>

#include "pmdplan/model/collision_shape.hpp"

namespace pmdplan {

/// Boxes, cylinders and spheres become FCL primitives; meshes (read with assimp, scaled) become
/// triangle BVH models. Throws InputError naming the mesh file if it cannot be read.
std::shared_ptr<fcl::CollisionGeometryd> makeFclGeometry(const Shape& shape);

/// Radius of a sphere about the shape's origin that encloses it (meshes: from their vertices).
double enclosingRadius(const Shape& shape, const fcl::CollisionGeometryd& geometry);

}  // namespace pmdplan
