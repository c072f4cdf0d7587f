#include "fcl_geometry.hpp"

#include "pmdplan/model/mesh_file.hpp"

namespace pmdplan {
namespace {

using Mesh = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<fcl::CollisionGeometryd> meshModel(const MeshShape& shape) {
  const TriangleMesh read = shape.triangles ? TriangleMesh{} : readMeshFile(shape.file, shape.scale);
  const TriangleMesh& mesh = shape.triangles ? *shape.triangles : read;
  std::vector<fcl::Vector3d> vertices(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  auto model = std::make_shared<Mesh>();
  model->beginModel();
  model->addSubModel(vertices, triangles);
  model->endModel();
  return model;
}

}  // namespace

std::shared_ptr<fcl::CollisionGeometryd> makeFclGeometry(const Shape& shape) {
  struct Visitor {
    std::shared_ptr<fcl::CollisionGeometryd> operator()(const BoxShape& b) const {
      return std::make_shared<fcl::Boxd>(b.size.x(), b.size.y(), b.size.z());
    }
    std::shared_ptr<fcl::CollisionGeometryd> operator()(const CylinderShape& c) const {
      return std::make_shared<fcl::Cylinderd>(c.radius, c.length);
    }
    std::shared_ptr<fcl::CollisionGeometryd> operator()(const SphereShape& s) const {
      return std::make_shared<fcl::Sphered>(s.radius);
    }
    std::shared_ptr<fcl::CollisionGeometryd> operator()(const MeshShape& m) const { return meshModel(m); }
  };
  auto geometry = std::visit(Visitor{}, shape);
  geometry->computeLocalAABB();
  return geometry;
}

double enclosingRadius(const Shape& shape, const fcl::CollisionGeometryd& geometry) {
  if (!std::holds_alternative<MeshShape>(shape)) return boundingRadius(shape);
  const auto& mesh = static_cast<const Mesh&>(geometry);
  double r = 0.0;
  for (int i = 0; i < mesh.num_vertices; ++i) r = std::max(r, mesh.vertices[i].norm());
  return r;
}

}  // namespace pmdplan
