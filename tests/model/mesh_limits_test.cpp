// Hostile mesh files within and beyond MeshLimits (model/mesh_file.hpp): each is refused with an
// InputError naming the file, quickly, before assimp builds much (a FIFO never blocks, a COLLADA
// instance_node cycle no longer overflows assimp's stack), or read as before.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <string>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/mesh_file.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::expectInputError;
const Eigen::Vector3d kOne = Eigen::Vector3d::Ones();

/// A COLLADA file: `geometryTriangles` triangles in geometry "g", then `libraryNodes` and the
/// scene's root node holding `sceneNode`.
std::string collada(int geometryTriangles, const std::string& libraryNodes, const std::string& sceneNode) {
  std::string indices;
  for (int t = 0; t < geometryTriangles; ++t) indices += "0 1 2 ";
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
      <technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count=")" +
         std::to_string(geometryTriangles) + R"("><input semantic="VERTEX" source="#v" offset="0"/><p>)" + indices +
         R"(</p></triangles>
  </mesh></geometry></library_geometries>
  <library_nodes>)" +
         libraryNodes + R"(</library_nodes>
  <library_visual_scenes><visual_scene id="s"><node id="root">)" +
         sceneNode + R"(</node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";
}

/// A binary STL whose header claims `count` triangles and whose size matches (sparse: zeros).
std::filesystem::path claimedStl(const test::TempDir& dir, std::uint32_t count) {
  const auto file = dir.path() / "claimed.stl";
  {
    std::ofstream out(file, std::ios::binary);
    const char header[80] = {};
    out.write(header, 80);
    out.write(reinterpret_cast<const char*>(&count), 4);
  }
  std::filesystem::resize_file(file, 84 + 50 * static_cast<std::uintmax_t>(count));
  return file;
}

TEST(MeshLimits, AColladaInstanceNodeCycleIsRefusedNotFollowed) {
  test::TempDir dir;
  const auto two =
      dir.write("cycle.dae", collada(1,
                                     "<node id=\"a\"><instance_node url=\"#b\"/><instance_geometry "
                                     "url=\"#g\"/></node><node id=\"b\"><instance_node url=\"#a\"/></node>",
                                     "<instance_node url=\"#a\"/>"));
  expectInputError([&] { readMeshFile(two, kOne); }, two.string(), "node", "cycle");
  const auto self = dir.write(
      "self.dae", collada(1, "<node id=\"a\"><instance_node url=\"#a\"/></node>", "<instance_geometry url=\"#g\"/>"));
  expectInputError([&] { readMeshFile(self, kOne); }, self.string(), "node 'a'", "cycle");
}

TEST(MeshLimits, ColladaNestingAndExpansionAreBounded) {
  test::TempDir dir;
  // A chain of 40 nodes, each instancing the next: deeper than kMaxColladaNodeDepth.
  std::string chain;
  for (int i = 0; i < 40; ++i)
    chain +=
        "<node id=\"n" + std::to_string(i) + "\">" +
        (i + 1 < 40 ? "<instance_node url=\"#n" + std::to_string(i + 1) + "\"/>" : "<instance_geometry url=\"#g\"/>") +
        "</node>";
  const auto deep = dir.write("deep.dae", collada(1, chain, "<instance_node url=\"#n0\"/>"));
  expectInputError([&] { readMeshFile(deep, kOne); }, deep.string(), "node", "nested more than 32");
  // 16 levels each instancing the next twice: 2^16 nodes once expanded, from a file of 2 KB.
  std::string doubling;
  for (int i = 0; i < 16; ++i) {
    const std::string next = "#d" + std::to_string(i + 1);
    doubling += "<node id=\"d" + std::to_string(i) + "\">" +
                (i + 1 < 16 ? "<instance_node url=\"" + next + "\"/><instance_node url=\"" + next + "\"/>"
                            : "<instance_geometry url=\"#g\"/>") +
                "</node>";
  }
  const auto wide = dir.write("wide.dae", collada(1, doubling, "<instance_node url=\"#d0\"/>"));
  expectInputError([&] { readMeshFile(wide, kOne); }, wide.string(), "node", "more than 10000 nodes");
}

TEST(MeshLimits, TrianglesCountEveryNodeInstance) {
  test::TempDir dir;
  // 25 triangles instanced 5,000 times: 125,000 triangles from a small file.
  std::string instances;
  for (int i = 0; i < 5000; ++i) instances += "<instance_node url=\"#leaf\"/>";
  const auto many =
      dir.write("many.dae", collada(25, "<node id=\"leaf\"><instance_geometry url=\"#g\"/></node>", instances));
  const auto began = std::chrono::steady_clock::now();
  expectInputError([&] { readMeshFile(many, kOne); }, many.string(), "mesh", "more than 100000 triangles");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count(), 5.0);
  // 25 x 3,000 = 75,000 triangles: read.
  std::string fewer;
  for (int i = 0; i < 3000; ++i) fewer += "<instance_node url=\"#leaf\"/>";
  const auto ok = dir.write("ok.dae", collada(25, "<node id=\"leaf\"><instance_geometry url=\"#g\"/></node>", fewer));
  EXPECT_EQ(readMeshFile(ok, kOne).triangles.size(), 75'000u);
}

TEST(MeshLimits, ABinaryStlClaimingTooManyTrianglesIsRefusedBeforeItIsRead) {
  test::TempDir dir;
  const auto stl = claimedStl(dir, 150'000);  // 7.5 MB of zeros, under the file bound
  expectInputError([&] { readMeshFile(stl, kOne); }, stl.string(), "triangle count", "at most 100000");
}

TEST(MeshLimits, AFileBeyondTheSizeBoundIsRefusedUnread) {
  test::TempDir dir;
  const auto big = dir.path() / "big.stl";
  std::ofstream(big) << "solid big\n";
  std::filesystem::resize_file(big, MeshLimits::kMaxFileBytes + 1);  // sparse
  expectInputError([&] { readMeshFile(big, kOne); }, big.string(), "mesh", "at most 16 MiB");
}

TEST(MeshLimits, AFifoIsRefusedWithoutBlocking) {
  test::TempDir dir;
  const auto fifo = dir.path() / "pipe.stl";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectInputError([&] { readMeshFile(fifo, kOne); }, fifo.string(), "mesh", "not a regular file");
  // A folder too.
  std::filesystem::create_directories(dir.path() / "folder.obj");
  expectInputError([&] { readMeshFile(dir.path() / "folder.obj", kOne); }, (dir.path() / "folder.obj").string(), "mesh",
                   "not a regular file");
}

TEST(MeshLimits, ObjFacesAreBoundedBeforeAssimpBuildsThem) {
  test::TempDir dir;
  std::string polygon = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
  for (int i = 0; i < 300; ++i) polygon += " " + std::to_string(i % 3 + 1);
  const auto big = dir.write("polygon.obj", polygon + "\n");
  expectInputError([&] { readMeshFile(big, kOne); }, big.string(), "line 4", "300 corners");
  std::string faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 100'001; ++i) faces += "f 1 2 3\n";
  const auto many = dir.write("many.obj", faces);
  expectInputError([&] { readMeshFile(many, kOne); }, many.string(), "line", "face corners");
}

TEST(MeshLimits, OnlyStlObjAndColladaAreReadAndTheExtensionChoosesTheReader) {
  test::TempDir dir;
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const auto asPly = dir.write("tri.ply", ply);
  expectInputError([&] { readMeshFile(asPly, kOne); }, asPly.string(), "mesh", "STL (.stl), OBJ (.obj) or COLLADA");
  // The same bytes named .stl are not handed to another of assimp's readers.
  const auto asStl = dir.write("tri.stl", ply);
  EXPECT_THROW(readMeshFile(asStl, kOne), InputError);
  // The extension's case does not matter.
  const auto upper = dir.write("TRI.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(readMeshFile(upper, kOne).triangles.size(), 1u);
}

TEST(MeshLimits, AnObjMaterialLibraryIsNeverOpened) {
  test::TempDir dir;
  const auto fifo = dir.path() / "materials.mtl";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);  // opening it would block
  const auto obj = dir.write(
      "tri.obj", "mtllib materials.mtl\nmtllib " + fifo.string() + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
  EXPECT_EQ(readMeshFile(obj, kOne).triangles.size(), 1u);
}

TEST(MeshLimits, ScaleAndVertexExtentAreBounded) {
  test::TempDir dir;
  const auto obj = dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  for (const double s : {-1.0, 0.0, 1e-7, 2e3})
    expectInputError([&] { readMeshFile(obj, Eigen::Vector3d(1, s, 1)); }, obj.string(), "scale", "scale factor");
  EXPECT_EQ(readMeshFile(obj, Eigen::Vector3d(100, 100, 100)).triangles.size(), 1u);  // 100 m: the bound
  expectInputError([&] { readMeshFile(obj, Eigen::Vector3d(101, 1, 1)); }, obj.string(), "vertex 2", "more than 100 m");
}

TEST(MeshLimits, TheMeshFuzzerSeedsAreMeshesWithinTheLimits) {
  const auto seeds = std::filesystem::path(PMDPLAN_TEST_DATA_DIR).parent_path() / "fuzz" / "corpus" / "mesh";
  int read = 0;
  for (const auto& entry : std::filesystem::directory_iterator(seeds)) {
    EXPECT_FALSE(readMeshFile(entry.path(), kOne).triangles.empty()) << entry.path();
    ++read;
  }
  EXPECT_GE(read, 5);
}

}  // namespace
}  // namespace pmdplan
