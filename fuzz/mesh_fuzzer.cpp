// A mesh file: the input's bytes read as each format pmdplan reads (STL, OBJ, COLLADA), through
// the checks before assimp, assimp itself and the bounds after it (model/mesh_file.hpp).
#include "fuzz_input.hpp"
#include "pmdplan/model/mesh_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = pmdplan::fuzz::asText(data, size);
  for (const char* name : {"mesh.stl", "mesh.obj", "mesh.dae"}) {
    const auto file = pmdplan::fuzz::writeScratch(name, bytes);
    pmdplan::fuzz::expectAcceptedOrInputError([&] { pmdplan::readMeshFile(file, Eigen::Vector3d::Ones()); });
  }
  return 0;
}
