#include "fcl_geometry.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cmath>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

using Mesh = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<fcl::CollisionGeometryd> loadMesh(const MeshShape& mesh) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(mesh.file.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (!scene || !scene->mRootNode) throw InputError(mesh.file.string(), "mesh", std::string("cannot read the mesh: ") + importer.GetErrorString());
  std::vector<fcl::Vector3d> vertices;
  std::vector<fcl::Triangle> triangles;
  // Walk the node tree so sub-meshes get their node transforms.
  std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack{{scene->mRootNode, scene->mRootNode->mTransformation}};
  while (!stack.empty()) {
    auto [node, transform] = stack.back();
    stack.pop_back();
    for (unsigned m = 0; m < node->mNumMeshes; ++m) {
      const aiMesh* part = scene->mMeshes[node->mMeshes[m]];
      const std::size_t offset = vertices.size();
      for (unsigned v = 0; v < part->mNumVertices; ++v) {
        const aiVector3D p = transform * part->mVertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          throw InputError(mesh.file.string(), "vertex " + std::to_string(v + 1), "not a finite point (NaN or infinite coordinates)");
        vertices.emplace_back(p.x * mesh.scale.x(), p.y * mesh.scale.y(), p.z * mesh.scale.z());
      }
      for (unsigned f = 0; f < part->mNumFaces; ++f) {
        const aiFace& face = part->mFaces[f];
        if (face.mNumIndices == 3)
          triangles.emplace_back(offset + face.mIndices[0], offset + face.mIndices[1], offset + face.mIndices[2]);
      }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c)
      stack.emplace_back(node->mChildren[c], transform * node->mChildren[c]->mTransformation);
  }
  if (triangles.empty()) throw InputError(mesh.file.string(), "mesh", "the mesh has no triangles");
  auto model = std::make_shared<Mesh>();
  model->beginModel();
  model->addSubModel(vertices, triangles);
  model->endModel();
  model->computeLocalAABB();
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
    std::shared_ptr<fcl::CollisionGeometryd> operator()(const MeshShape& m) const { return loadMesh(m); }
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
