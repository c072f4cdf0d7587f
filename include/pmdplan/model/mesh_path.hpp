#pragma once
// Where a mesh file named in a robot or task file is: the one place that turns a written mesh
// path into a file. Absolute paths stay (a file:// prefix is dropped); relative paths are
// relative to the folder of the file that names them.
#include <filesystem>
#include <string>

namespace pmdplan {

/// The absolute, normalised path of the mesh `written` in `referringFile` (at key `field`).
/// InputError naming referringFile and field if it is empty, a form not read here (a URI scheme
/// such as package://), or not an existing file.
std::filesystem::path resolveMeshPath(const std::string& written, const std::filesystem::path& referringFile,
                                      const std::string& field);

}  // namespace pmdplan
