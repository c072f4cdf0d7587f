#include "pmdplan/model/mesh_file.hpp"

#include <assimp/MemoryIOWrapper.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <utility>

#include "mesh_scan.hpp"
#include "pmdplan/core/command_files.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

std::string lowerExtension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

/// The file's bytes: a regular file (stat first: opening a FIFO could block) of at most
/// MeshLimits::kMaxFileBytes.
std::string readMeshBytes(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string limit = std::to_string(MeshLimits::kMaxFileBytes >> 20) + " MiB";
  struct stat status {};
  if (::stat(file.c_str(), &status) != 0)
    throw InputError(name, "mesh", std::string("cannot read the mesh: ") + std::strerror(errno));
  const auto check = [&](const struct stat& s) {
    if (!S_ISREG(s.st_mode))
      throw InputError(name, "mesh", "is not a regular file (a folder, pipe or device); a mesh must be a regular file");
    if (static_cast<std::uintmax_t>(s.st_size) > MeshLimits::kMaxFileBytes)
      throw InputError(name, "mesh",
                       "the file has " + std::to_string(s.st_size) + " bytes; a mesh file may have at most " + limit);
  };
  check(status);
  // O_NONBLOCK: should the file be swapped for a FIFO since the stat, opening it does not wait.
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw InputError(name, "mesh", std::string("cannot read the mesh: ") + std::strerror(errno));
  std::string bytes;
  try {
    if (::fstat(fd, &status) != 0)
      throw InputError(name, "mesh", std::string("cannot read the mesh: ") + std::strerror(errno));
    check(status);
    bytes.resize(static_cast<std::size_t>(status.st_size));
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw InputError(name, "mesh", std::string("read failed: ") + std::strerror(errno));
      if (n == 0) break;  // the file shrank meanwhile
      done += static_cast<std::size_t>(n);
    }
    bytes.resize(done);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return bytes;
}

/// assimp's file access for one import: the mesh's bytes under `name`, and no other file (an OBJ's
/// material library, say: a path in a hostile file could name a FIFO or a secret).
class OneFileIOSystem : public Assimp::IOSystem {
 public:
  OneFileIOSystem(std::string name, const std::string& bytes) : name_(std::move(name)), bytes_(bytes) {}
  bool Exists(const char* file) const override { return file && name_ == file; }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (!Exists(file) || !mode || std::strchr(mode, 'w') || std::strchr(mode, 'a')) return nullptr;
    return new Assimp::MemoryIOStream(reinterpret_cast<const std::uint8_t*>(bytes_.data()), bytes_.size());
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }

 private:
  std::string name_;
  const std::string& bytes_;
};

/// Bounds the faces assimp read, before the triangulation (quadratic in a polygon's corners) runs.
void checkFaces(const aiScene& scene, const std::string& name) {
  std::size_t triangles = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* part = scene.mMeshes[m];
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const std::size_t corners = part->mFaces[f].mNumIndices;
      if (corners > MeshLimits::kMaxPolygonCorners)
        throw InputError(name, "face " + std::to_string(f + 1) + " of mesh " + std::to_string(m + 1),
                         "a polygon of " + std::to_string(corners) + " corners; at most " +
                             std::to_string(MeshLimits::kMaxPolygonCorners) + " are read");
      if (corners >= 3) triangles += corners - 2;
    }
    if (triangles > MeshLimits::kMaxTriangles)
      throw InputError(
          name, "mesh",
          "more than " + std::to_string(MeshLimits::kMaxTriangles) + " triangles, the most a mesh may have");
  }
}

}  // namespace

const std::vector<std::string>& meshFileExtensions() {
  static const std::vector<std::string> extensions{".stl", ".obj", ".dae"};
  return extensions;
}

bool hasMeshFileExtension(const std::filesystem::path& file) {
  const auto& extensions = meshFileExtensions();
  return std::find(extensions.begin(), extensions.end(), lowerExtension(file)) != extensions.end();
}

TriangleMesh readMeshFile(const std::filesystem::path& file, const Eigen::Vector3d& scale) {
  const std::string name = file.string();
  recordInputFile(file);  // no output of the command may replace it (core/command_files.hpp)
  if (!hasMeshFileExtension(file))
    throw InputError(name, "mesh", "expected an STL (.stl), OBJ (.obj) or COLLADA (.dae) mesh file");
  if (auto problem = shapeBoundsProblem(MeshShape{file, scale, nullptr}))
    throw InputError(name, "scale", problem->message);
  const std::string extension = lowerExtension(file);
  const std::string bytes = readMeshBytes(file);
  if (extension == ".obj") mesh_scan::checkObj(bytes, name);
  if (extension == ".stl") mesh_scan::checkStl(bytes, name);
  if (extension == ".dae") mesh_scan::checkCollada(bytes, name);

  Assimp::Importer importer;
  const std::string inMemory = "mesh" + extension;              // the extension chooses assimp's importer
  importer.SetIOHandler(new OneFileIOSystem(inMemory, bytes));  // the importer owns it
  // Not aiProcess_JoinIdenticalVertices: it merges a NaN vertex into another one, hiding it.
  const aiScene* scene = importer.ReadFile(inMemory, 0);
  if (!scene || !scene->mRootNode)
    throw InputError(name, "mesh", std::string("cannot read the mesh: ") + importer.GetErrorString());
  checkFaces(*scene, name);
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate);
  if (!scene || !scene->mRootNode)
    throw InputError(name, "mesh", std::string("cannot read the mesh: ") + importer.GetErrorString());
  TriangleMesh mesh;
  // Walk the node tree so that sub-meshes get their node transforms; every instance of a mesh counts.
  std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack{{scene->mRootNode, scene->mRootNode->mTransformation}};
  while (!stack.empty()) {
    auto [node, transform] = stack.back();
    stack.pop_back();
    for (unsigned m = 0; m < node->mNumMeshes; ++m) {
      if (node->mMeshes[m] >= scene->mNumMeshes)
        throw InputError(name, "mesh", "a node names a mesh the file does not have");
      const aiMesh* part = scene->mMeshes[node->mMeshes[m]];
      const std::string partName = "mesh " + std::to_string(node->mMeshes[m] + 1);
      if (mesh.triangles.size() + part->mNumFaces > MeshLimits::kMaxTriangles)
        throw InputError(name, "mesh",
                         "more than " + std::to_string(MeshLimits::kMaxTriangles) +
                             " triangles (every node instance counted), the most a mesh may have");
      const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
      for (unsigned v = 0; v < part->mNumVertices; ++v) {
        const aiVector3D raw = part->mVertices[v];
        const aiVector3D p = transform * raw;
        const Eigen::Vector3d vertex(p.x * scale.x(), p.y * scale.y(), p.z * scale.z());
        const std::string field = "vertex " + std::to_string(v + 1) + " of " + partName;
        if (!vertex.allFinite())
          throw InputError(name, field,
                           "expected three finite coordinates, got " + std::to_string(raw.x) + " " +
                               std::to_string(raw.y) + " " + std::to_string(raw.z));
        if (vertex.cwiseAbs().maxCoeff() > ShapeBounds::kMaxLength)
          throw InputError(name, field,
                           "lies more than " + std::to_string(static_cast<int>(ShapeBounds::kMaxLength)) +
                               " m from the mesh's frame once placed and scaled; a shape is at most that large");
        mesh.vertices.push_back(vertex);
      }
      for (unsigned f = 0; f < part->mNumFaces; ++f) {
        const aiFace& face = part->mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines
        for (unsigned k = 0; k < 3; ++k)
          if (face.mIndices[k] >= part->mNumVertices)
            throw InputError(name, "face " + std::to_string(f + 1) + " of " + partName,
                             "names a vertex the mesh does not have");
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
  MeshShape shape{file, scale, nullptr};
  shape.triangles = std::make_shared<const TriangleMesh>(readMeshFile(file, scale));
  return shape;
}

void MeshTriangleBudget::add(const MeshShape& mesh, const std::string& file, const std::string& field) {
  if (!mesh.triangles) return;
  total_ += mesh.triangles->triangles.size();
  if (total_ > MeshLimits::kMaxTrianglesTogether)
    throw InputError(file, field,
                     "the " + what_ + " have more than " + std::to_string(MeshLimits::kMaxTrianglesTogether) +
                         " triangles together, the most pmdplan reads (" + std::to_string(MeshLimits::kMaxTriangles) +
                         " per mesh)");
}

}  // namespace pmdplan
