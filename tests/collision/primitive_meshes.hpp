#pragma once
// Test robots whose collision geometry is all meshes: every box, cylinder and sphere of a URDF
// replaced by a triangulated unit shape in an ASCII STL file, sized by the mesh's scale
// attribute. Inscribed tessellations (vertices on the primitive's surface) lie inside the
// primitive; circumscribed ones (faces tangent to it or outside) contain it. Used by the tests and
// by benchmarks/collision_check_bench.cpp.
#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan::testing {

enum class Tessellation { Inscribed, Circumscribed };

struct MeshTriangle {
  Eigen::Vector3d a, b, c;
};

inline std::string stlText(const std::vector<MeshTriangle>& triangles) {
  std::ostringstream out;
  out.precision(17);
  out << "solid shape\n";
  for (const auto& t : triangles) {
    const Eigen::Vector3d n = (t.b - t.a).cross(t.c - t.a).normalized();
    out << "facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n outer loop\n";
    for (const auto* v : {&t.a, &t.b, &t.c}) out << "  vertex " << v->x() << ' ' << v->y() << ' ' << v->z() << '\n';
    out << " endloop\nendfacet\n";
  }
  out << "endsolid shape\n";
  return out.str();
}

/// The unit cube [-0.5, 0.5]^3 (exact either way).
inline std::vector<MeshTriangle> unitBox() {
  std::vector<MeshTriangle> out;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-0.5, 0.5}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Eigen::Vector3d corner[4];
      for (int k = 0; k < 4; ++k) {
        corner[k][axis] = side;
        corner[k][u] = (k == 1 || k == 2) ? 0.5 : -0.5;
        corner[k][v] = (k >= 2) ? 0.5 : -0.5;
      }
      out.push_back({corner[0], corner[1], corner[2]});
      out.push_back({corner[0], corner[2], corner[3]});
    }
  return out;
}

/// The cylinder of radius 1 and length 1 along z, as a prism over a regular `sides`-gon.
inline std::vector<MeshTriangle> unitCylinder(Tessellation kind, int sides = 16) {
  const double pi = 3.14159265358979323846;
  const double r = kind == Tessellation::Inscribed ? 1.0 : 1.0 / std::cos(pi / sides);
  std::vector<MeshTriangle> out;
  const Eigen::Vector3d top(0, 0, 0.5), bottom(0, 0, -0.5);
  for (int k = 0; k < sides; ++k) {
    const double a0 = 2 * pi * k / sides, a1 = 2 * pi * (k + 1) / sides;
    const Eigen::Vector3d p0(r * std::cos(a0), r * std::sin(a0), 0), p1(r * std::cos(a1), r * std::sin(a1), 0);
    out.push_back({bottom + p0, bottom + p1, top + p1});
    out.push_back({bottom + p0, top + p1, top + p0});
    out.push_back({top, top + p0, top + p1});
    out.push_back({bottom, bottom + p1, bottom + p0});
  }
  return out;
}

/// The unit sphere as a latitude-longitude polyhedron (its quads are planar, so it is convex);
/// circumscribed: scaled until every face plane is at least 1 from the centre.
inline std::vector<MeshTriangle> unitSphere(Tessellation kind, int stacks = 6, int slices = 10) {
  const double pi = 3.14159265358979323846;
  const auto point = [&](int i, int j) {
    const double polar = pi * i / stacks, azimuth = 2 * pi * j / slices;
    return Eigen::Vector3d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
  };
  std::vector<MeshTriangle> out;
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const Eigen::Vector3d a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
      if (i > 0) out.push_back({a, b, d});
      if (i + 1 < stacks) out.push_back({b, c, d});
    }
  if (kind == Tessellation::Circumscribed) {
    double nearest = 1.0;
    for (const auto& t : out) nearest = std::min(nearest, std::abs((t.b - t.a).cross(t.c - t.a).normalized().dot(t.a)));
    const double grow = (1.0 / nearest) * (1.0 + 1e-12);
    for (auto& t : out) t.a *= grow, t.b *= grow, t.c *= grow;
  }
  return out;
}

inline std::string vectorText(double x, double y, double z) {
  std::ostringstream out;
  out.precision(17);
  out << x << ' ' << y << ' ' << z;
  return out.str();
}

/// Writes `dir`/NAME.urdf: the URDF `urdf` with every primitive collision geometry a mesh in
/// dir/meshes/, and NAME.srdf copied from `srdf`. Returns the URDF's path.
inline std::filesystem::path writeMeshRobot(const test::TempDir& dir, const std::filesystem::path& urdf,
                                            const std::filesystem::path& srdf, const std::string& name,
                                            Tessellation kind) {
  dir.write("meshes/box.stl", stlText(unitBox()));
  dir.write("meshes/cylinder.stl", stlText(unitCylinder(kind)));
  dir.write("meshes/sphere.stl", stlText(unitSphere(kind)));
  tinyxml2::XMLDocument document;
  if (document.LoadFile(urdf.string().c_str()) != tinyxml2::XML_SUCCESS)
    throw std::runtime_error("cannot read " + urdf.string());
  for (auto* link = document.RootElement()->FirstChildElement("link"); link; link = link->NextSiblingElement("link"))
    for (auto* collision = link->FirstChildElement("collision"); collision;
         collision = collision->NextSiblingElement("collision")) {
      auto* geometry = collision->FirstChildElement("geometry");
      auto* shape = geometry->FirstChildElement();
      const std::string type = shape->Name();
      std::string file, scale;
      if (type == "box") {
        double x, y, z;
        std::istringstream(shape->Attribute("size")) >> x >> y >> z;
        file = "meshes/box.stl", scale = vectorText(x, y, z);
      } else if (type == "cylinder") {
        const double r = shape->DoubleAttribute("radius"), length = shape->DoubleAttribute("length");
        file = "meshes/cylinder.stl", scale = vectorText(r, r, length);
      } else if (type == "sphere") {
        const double r = shape->DoubleAttribute("radius");
        file = "meshes/sphere.stl", scale = vectorText(r, r, r);
      } else {
        continue;
      }
      geometry->DeleteChildren();
      auto* mesh = geometry->InsertNewChildElement("mesh");
      mesh->SetAttribute("filename", file.c_str());
      mesh->SetAttribute("scale", scale.c_str());
    }
  tinyxml2::XMLPrinter printer;
  document.Print(&printer);
  dir.write(name + ".srdf", readTextFile(srdf));
  return dir.write(name + ".urdf", printer.CStr());
}

/// The text of the built-in task `name` with `robot:` set to `robot`.
inline std::string builtInTaskText(const std::string& name, const std::string& robot) {
  std::string text = readTextFile(dataDirectory() / "scenes" / (name + ".yaml"));
  const std::string line = "robot: sah_tx90\n";
  text.replace(text.find(line), line.size(), "robot: " + robot + "\n");
  return text;
}

}  // namespace pmdplan::testing
