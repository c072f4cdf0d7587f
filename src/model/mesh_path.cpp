#include "pmdplan/model/mesh_path.hpp"

#include <system_error>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

std::filesystem::path resolveMeshPath(const std::string& written, const std::filesystem::path& referringFile,
                                      const std::string& field) {
  if (written.empty()) throw InputError(referringFile.string(), field, "expected a mesh file path, got an empty string");
  const std::string fileScheme = "file://";
  const std::string plain = written.rfind(fileScheme, 0) == 0 ? written.substr(fileScheme.size()) : written;
  if (plain.find("://") != std::string::npos)
    throw InputError(referringFile.string(), field,
                     "mesh path '" + written + "': expected a file path (absolute, or relative to this file), not a URI");
  std::filesystem::path path = plain;
  if (path.is_relative()) path = referringFile.parent_path() / path;
  path = std::filesystem::absolute(path).lexically_normal();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(referringFile.string(), field,
                     "mesh file not found: " + path.string() + " (relative paths are relative to this file)");
  return path;
}

}  // namespace pmdplan
