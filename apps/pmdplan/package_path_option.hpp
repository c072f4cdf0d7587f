#pragma once
// `--package-path DIR[:DIR]` for every command that loads a robot: where package:// references
// of URDFs, meshes and task files are looked up (before PMDPLAN_PACKAGE_PATH).
#include <CLI/CLI.hpp>

#include "pmdplan/model/resource_path.hpp"

namespace pmdplan::cli {

inline void addPackagePathOption(CLI::App& app) {
  app.add_option_function<std::string>(
      "--package-path", [](const std::string& text) { setPackageSearchPath(PackageSearchPath::parse(text)); },
      "Colon-separated directories holding ROS-style packages (DIR/NAME/...) for package:// paths; "
      "searched before $PMDPLAN_PACKAGE_PATH");
}

}  // namespace pmdplan::cli
