// Task files with obstacles beyond ShapeBounds (model/collision_shape.hpp), too many mesh triangles
// together, and names that are not plain: each one InputError naming the file and the field.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pmdplan/model/mesh_file.hpp"
#include "toy_task_files.hpp"

namespace pmdplan {
namespace {

using test::kValidToyTask;
using test::replaceOnce;
using test::ToyTaskFolder;
using ::testing::HasSubstr;
using ::testing::Not;

class TaskGeometryBounds : public ::testing::Test {
 protected:
  ToyTaskFolder folder;

  /// The InputError loading `text` raises (a failure if none).
  InputError errorFor(const std::string& text) {
    const auto path = folder.write("task.yaml", text);
    try {
      loadTask(path);
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), path.string());
      return error;
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return InputError("", "", "");
  }
};

TEST_F(TaskGeometryBounds, ObstacleSizesOutsideTheBoundsAreRefused) {
  auto error = errorFor(replaceOnce(kValidToyTask, "box: [0.5, 0.4, 0.3]", "box: [1e300, 0.4, 0.3]"));
  EXPECT_THAT(error.field(), HasSubstr("obstacles[0].box[0] (line"));
  EXPECT_THAT(error.message(), HasSubstr("from 1e-06 to 100, got 1e+300"));
  error = errorFor(replaceOnce(kValidToyTask, "box: [0.5, 0.4, 0.3]", "box: [1e10, 1e10, 1e10]"));
  EXPECT_THAT(error.field(), HasSubstr("obstacles[0].box[0]"));
  error = errorFor(replaceOnce(kValidToyTask, "sphere: 0.05", "sphere: 1e20"));
  EXPECT_THAT(error.field(), HasSubstr("obstacles[2].sphere"));
  error = errorFor(replaceOnce(kValidToyTask, "length: 0.12", "length: 100.01"));
  EXPECT_THAT(error.field(), HasSubstr("obstacles[1].cylinder.length"));
  error = errorFor(replaceOnce(kValidToyTask, "radius: 0.03", "radius: 1e-9"));
  EXPECT_THAT(error.field(), HasSubstr("obstacles[1].cylinder.radius"));
  error = errorFor(replaceOnce(kValidToyTask, "scale: [0.001, 0.002, 0.003]", "scale: [0.001, 1e6, 0.003]"));
  EXPECT_THAT(error.field(), HasSubstr("obstacles[3].mesh.scale[1]"));
  // The largest allowed obstacle loads.
  EXPECT_NO_THROW(loadTask(
      folder.write("big.yaml", replaceOnce(kValidToyTask, "box: [0.5, 0.4, 0.3]", "box: [100, 100, 0.000001]"))));
}

TEST_F(TaskGeometryBounds, PositionsBeyondTheBoundAreRefused) {
  auto error = errorFor(replaceOnce(kValidToyTask, "xyz: [1.0, 0.0, 0.15]", "xyz: [1e300, 0.0, 0.15]"));
  EXPECT_THAT(error.field(), HasSubstr("obstacles[0].xyz[0]"));
  EXPECT_THAT(error.message(), HasSubstr("from -1000 to 1000"));
  error = errorFor(replaceOnce(kValidToyTask, "base: {xyz: [0.1, 0.2, 0.0]", "base: {xyz: [0.1, -1000.5, 0.0]"));
  EXPECT_THAT(error.field(), HasSubstr("base.xyz[1]"));
}

TEST_F(TaskGeometryBounds, ObstacleMeshTrianglesTogetherAreBounded) {
  // One COLLADA mesh of 20 triangles instanced 4,000 times: 80,000 triangles, within the bound of
  // a mesh; three obstacles of it pass the bound of a task's meshes together.
  std::string instances, indices;
  for (int i = 0; i < 4000; ++i) instances += "<instance_node url=\"#leaf\"/>";
  for (int i = 0; i < 20; ++i) indices += "0 1 2 ";
  folder.write(
      "meshes/many.dae",
      R"(<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="9">0 0 0 0.01 0 0 0 0.01 0</float_array>
<technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices><triangles count="20"><input semantic="VERTEX" source="#v" offset="0"/><p>)" +
          indices + R"(</p></triangles></mesh></geometry></library_geometries>
<library_nodes><node id="leaf"><instance_geometry url="#g"/></node></library_nodes>
<library_visual_scenes><visual_scene id="s"><node id="root">)" +
          instances +
          R"(</node></visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>
)");
  std::string more;
  for (int i = 0; i < 2; ++i)
    more += "  - {name: more" + std::to_string(i) + ", mesh: {file: meshes/many.dae}, xyz: [2, 2, " +
            std::to_string(i) + "]}\n";
  const std::string task = replaceOnce(replaceOnce(kValidToyTask, "meshes/part.stl", "meshes/many.dae"),
                                       "    rpy_deg: [90, 0, 90]\n", "    rpy_deg: [90, 0, 90]\n" + more);
  const auto error = errorFor(task);
  EXPECT_THAT(error.field(), HasSubstr("obstacles[5]"));
  EXPECT_THAT(error.message(), HasSubstr("more than 200000 triangles together"));
}

TEST_F(TaskGeometryBounds, ANameThatIsNotPlainIsRefusedWithoutShowingIt) {
  const auto refused = [&](const std::string& yamlName, const std::string& shown) {
    const auto error = errorFor(replaceOnce(kValidToyTask, "name: toy_task", "name: " + yamlName));
    EXPECT_THAT(error.field(), HasSubstr("name (line 1)")) << yamlName;
    EXPECT_THAT(error.message(), HasSubstr("expected a plain task name")) << yamlName;
    EXPECT_THAT(error.message(), HasSubstr(shown)) << yamlName;
    EXPECT_THAT(std::string(error.what()), Not(HasSubstr("\x1b"))) << yamlName;
  };
  refused("a/../../escaped", "'/' at character 2");
  refused("../escaped", "starting with '.'");
  refused("/tmp/absolute", "'/' at character 1");
  refused("\"\\e[31mred\"", "\\x1B at character 1");
  refused("\"tab\\tname\"", "\\x09 at character 4");
  refused(".hidden", "starting with '.'");
  refused("\"two words\"", "\\x20 at character 4");
  refused(std::string(101, 'a'), "a name of 101 characters");
  refused("\"caf\\u00e9\"", "\\xC3 at character 4");
  for (const std::string& name : std::vector<std::string>{"can_on_table", "T-1.2", std::string(100, 'x')})
    EXPECT_NO_THROW(loadTask(folder.write("ok.yaml", replaceOnce(kValidToyTask, "name: toy_task", "name: " + name))))
        << name;
}

}  // namespace
}  // namespace pmdplan
