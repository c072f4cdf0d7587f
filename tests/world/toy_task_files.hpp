#pragma once
// A temporary folder holding a small three-joint robot (toy.urdf), a mesh and task files written by
// the tests, so the task loader can be exercised without the built-in hand-arm model.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::test {

/// Revolute shoulder (-90..90 deg), elbow (-30..120 deg, the upper limit written in radians as a
/// URDF would), wrist (-180..180 deg); `tip` mimics the wrist; `mount` is fixed.
inline constexpr const char* kToyUrdf = R"(<?xml version="1.0"?>
<robot name="toy">
  <link name="base"><collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0 0 0.15"/><geometry><cylinder radius="0.03" length="0.3"/></geometry></collision></link>
  <link name="fore"><collision><origin xyz="0 0 0.1"/><geometry><cylinder radius="0.02" length="0.2"/></geometry></collision></link>
  <link name="hand"><collision><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="finger"><collision><geometry><sphere radius="0.01"/></geometry></collision></link>
  <link name="camera"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 0 1"/><limit lower="-1.5707963267948966" upper="1.5707963267948966" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 1 0"/><limit lower="-0.5235987755982988" upper="2.0943951023931957" effort="1" velocity="1"/></joint>
  <joint name="wrist" type="revolute"><parent link="fore"/><child link="hand"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 1 0"/><limit lower="-3.141592653589793" upper="3.141592653589793" effort="1" velocity="1"/></joint>
  <joint name="tip" type="revolute"><parent link="hand"/><child link="finger"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 1 0"/><limit lower="-3.141592653589793" upper="3.141592653589793" effort="1" velocity="1"/>
    <mimic joint="wrist" multiplier="1" offset="0"/></joint>
  <joint name="mount" type="fixed"><parent link="base"/><child link="camera"/><origin xyz="0.1 0 0"/></joint>
</robot>
)";

/// A tiny ASCII STL (one tetrahedron) for mesh obstacles.
inline constexpr const char* kTetrahedronStl = R"(solid tetra
facet normal 0 0 -1
 outer loop
  vertex 0 0 0
  vertex 1 0 0
  vertex 0 1 0
 endloop
endfacet
facet normal 0 -1 0
 outer loop
  vertex 0 0 0
  vertex 0 0 1
  vertex 1 0 0
 endloop
endfacet
facet normal -1 0 0
 outer loop
  vertex 0 0 0
  vertex 0 1 0
  vertex 0 0 1
 endloop
endfacet
facet normal 0.577 0.577 0.577
 outer loop
  vertex 1 0 0
  vertex 0 0 1
  vertex 0 1 0
 endloop
endfacet
endsolid tetra
)";

/// A task that loads: every kind of obstacle, a target, start in degrees and goal in radians.
inline constexpr const char* kValidToyTask = R"(name: toy_task
description: a toy robot for the loader tests
robot: toy.urdf
base: {xyz: [0.1, 0.2, 0.0], rpy_deg: [0, 0, 90]}
target: can
obstacles:
  - {name: table, box: [0.5, 0.4, 0.3], xyz: [1.0, 0.0, 0.15]}
  - name: can
    cylinder:
      radius: 0.03
      length: 0.12
    xyz: [1.0, 0.1, 0.36]
    rpy_deg: [90, 0, 0]
  - {name: ball, sphere: 0.05, xyz: [0, 0, 1]}
  - name: part
    mesh: {file: meshes/part.stl, scale: [0.001, 0.002, 0.003]}
    xyz: [0, 0.5, 1]
    rpy_deg: [90, 0, 90]
start:
  joints_deg:
    shoulder: 10
    elbow: 20
    wrist: -30
goal:
  joints: {wrist: 0.25, shoulder: -0.5, elbow: 1.0}
)";

/// A fresh folder per test with toy.urdf and meshes/part.stl; removed afterwards.
class ToyTaskFolder {
 public:
  ToyTaskFolder() {
    static std::atomic<int> counter{0};
    directory_ = std::filesystem::temp_directory_path() /
                 ("pmdplan_world_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_ / "meshes");
    write("toy.urdf", kToyUrdf);
    write("meshes/part.stl", kTetrahedronStl);
  }
  ~ToyTaskFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(directory_, ignored);
  }
  ToyTaskFolder(const ToyTaskFolder&) = delete;
  ToyTaskFolder& operator=(const ToyTaskFolder&) = delete;

  const std::filesystem::path& directory() const { return directory_; }

  std::filesystem::path write(const std::string& relativePath, const std::string& text) const {
    const auto path = directory_ / relativePath;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return path;
  }

 private:
  std::filesystem::path directory_;
};

/// `text` with the one occurrence of `from` replaced by `to`; fails the test if `from` is not
/// there exactly once (so a mutation never silently misses).
inline std::string replaceOnce(const std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' not in the task text";
  if (at == std::string::npos) return text;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "'" << from << "' occurs twice";
  return text.substr(0, at) + to + text.substr(at + from.size());
}

/// 1-based line of the first occurrence of `needle` in `text` (0 if absent).
inline int lineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  if (at == std::string::npos) return 0;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

}  // namespace pmdplan::test
