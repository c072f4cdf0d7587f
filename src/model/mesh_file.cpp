#include "pmdplan/model/mesh_file.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

TriangleMesh readMeshFile(const std::filesystem::path& file, const Eigen::Vector3d& scale) {
  const std::string name = file.string();
  if (!scale.allFinite()) throw InputError(name, "scale", "expected finite scale factors");
  Assimp::Importer importer;
  // Not aiProcess_JoinIdenticalVertices: it merges a NaN vertex into another one, hiding it.
  const aiScene* scene = importer.ReadFile(name, aiProcess_Triangulate);
  if (!scene || !scene->mRootNode)
    throw InputError(name, "mesh", std::string("cannot read the mesh: ") + importer.GetErrorString());
  TriangleMesh mesh;
  // Walk the node tree so that sub-meshes get their node transforms.
  std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack{{scene->mRootNode, scene->mRootNode->mTransformation}};
  while (!stack.empty()) {
    auto [node, transform] = stack.back();
    stack.pop_back();
    for (unsigned m = 0; m < node->mNumMeshes; ++m) {
      const aiMesh* part = scene->mMeshes[node->mMeshes[m]];
      const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
      for (unsigned v = 0; v < part->mNumVertices; ++v) {
        const aiVector3D raw = part->mVertices[v];
        const aiVector3D p = transform * raw;
        const Eigen::Vector3d vertex(p.x * scale.x(), p.y * scale.y(), p.z * scale.z());
        if (!vertex.allFinite())
          throw InputError(name, "vertex " + std::to_string(v + 1) + " of mesh " + std::to_string(node->mMeshes[m] + 1),
                           "expected three finite coordinates, got " + std::to_string(raw.x) + " " +
                               std::to_string(raw.y) + " " + std::to_string(raw.z));
        mesh.vertices.push_back(vertex);
      }
      for (unsigned f = 0; f < part->mNumFaces; ++f) {
        const aiFace& face = part->mFaces[f];
        if (face.mNumIndices == 3)
          mesh.triangles.push_back({offset + face.mIndices[0], offset + face.mIndices[1], offset + face.mIndices[2]});
      }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c)
      stack.emplace_back(node->mChildren[c], transform * node->mChildren[c]->mTransformation);
  }
  if (mesh.triangles.empty()) throw InputError(name, "mesh", "expected triangles, the mesh has none");
  return mesh;
}

MeshShape loadMeshShape(const std::filesystem::path& file, const Eigen::Vector3d& scale) {
  MeshShape shape{file, scale};
  shape.triangles = std::make_shared<const TriangleMesh>(readMeshFile(file, scale));
  return shape;
}

}  // namespace pmdplan
