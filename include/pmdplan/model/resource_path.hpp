#pragma once
// Paths as URDF authors write them: `package://NAME/rest` (found through a package search path,
// like ROS's), `file:///absolute` and plain paths (relative to the file that names them). The one
// place that turns such a reference into a file, for robot files, meshes and task `robot:` keys.
#include <filesystem>
#include <string>
#include <vector>

namespace pmdplan {

/// Directories each holding packages as sub-directories (DIR/NAME/...), searched in order.
struct PackageSearchPath {
  std::vector<std::filesystem::path> directories;

  /// A colon-separated list as `--package-path` and PMDPLAN_PACKAGE_PATH take it; empty entries
  /// are skipped.
  static PackageSearchPath parse(const std::string& colonSeparated);
  /// "DIR:DIR" for messages, or "(empty)".
  std::string text() const;
};

/// The process's search path: the directories given to setPackageSearchPath (the CLI's
/// `--package-path`), then those of the PMDPLAN_PACKAGE_PATH environment variable.
PackageSearchPath packageSearchPath();
void setPackageSearchPath(PackageSearchPath path);

/// Resolves `reference` as written in `referencingFile` at `field` (for messages): package:// through
/// packageSearchPath(), file:// to its path, anything else relative to the referencing file's
/// directory. The file must exist; otherwise InputError naming the referencing file, the field, the
/// reference and (for package://) the search path tried, with how to extend it.
std::filesystem::path resolveResourcePath(const std::string& reference, const std::filesystem::path& referencingFile,
                                          const std::string& field);

}  // namespace pmdplan
