#include "pmdplan/model/resource_path.hpp"

#include <cstdlib>
#include <mutex>
#include <sstream>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

std::mutex searchPathMutex;
PackageSearchPath configuredSearchPath;

constexpr const char* kPackagePrefix = "package://";
constexpr const char* kFilePrefix = "file://";

bool startsWith(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

std::filesystem::path resolvePackage(const std::string& reference, const std::filesystem::path& referencingFile,
                                     const std::string& field) {
  const std::string rest = reference.substr(std::string(kPackagePrefix).size());
  const auto slash = rest.find('/');
  const std::string package = rest.substr(0, slash);
  const std::string inside = slash == std::string::npos ? std::string() : rest.substr(slash + 1);
  if (package.empty() || package == "." || package == "..")
    throw InputError(referencingFile.string(), field, "'" + reference + "': expected package://NAME/path/in/package");
  // The path must stay inside the package: `package://pkg/../../etc/passwd` is refused, not followed.
  // (Symbolic links inside the package are followed, as ROS does: colcon --symlink-install makes them.)
  const std::filesystem::path relative = std::filesystem::path(inside).lexically_normal();
  if (relative.is_absolute() || (!relative.empty() && *relative.begin() == ".."))
    throw InputError(referencingFile.string(), field,
                     "'" + reference + "' leaves the folder of package '" + package +
                         "'; expected a path inside the package (no '..' above it)");
  const PackageSearchPath searchPath = packageSearchPath();
  std::error_code error;
  for (const auto& directory : searchPath.directories) {
    const auto packageDirectory = directory / package;
    if (!std::filesystem::is_directory(packageDirectory, error)) continue;
    const auto file = (packageDirectory / inside).lexically_normal();
    if (std::filesystem::exists(file, error)) return file;
    throw InputError(referencingFile.string(), field,
                     "'" + reference + "': package '" + package + "' is " + packageDirectory.string() +
                         " but it holds no " + inside);
  }
  throw InputError(referencingFile.string(), field,
                   "'" + reference + "': no package '" + package + "' in the package search path " + searchPath.text() +
                       "; add the directory that holds " + package +
                       "/ with --package-path DIR[:DIR] or "
                       "PMDPLAN_PACKAGE_PATH=DIR[:DIR]");
}

}  // namespace

PackageSearchPath PackageSearchPath::parse(const std::string& colonSeparated) {
  PackageSearchPath path;
  std::stringstream in(colonSeparated);
  std::string entry;
  while (std::getline(in, entry, ':'))
    if (!entry.empty()) path.directories.emplace_back(entry);
  return path;
}

std::string PackageSearchPath::text() const {
  if (directories.empty()) return "(empty)";
  std::string out;
  for (const auto& directory : directories) {
    if (!out.empty()) out += ':';
    out += directory.string();
  }
  return out;
}

PackageSearchPath packageSearchPath() {
  PackageSearchPath path;
  {
    std::lock_guard lock(searchPathMutex);
    path = configuredSearchPath;
  }
  if (const char* env = std::getenv("PMDPLAN_PACKAGE_PATH"); env && *env)
    for (auto& directory : PackageSearchPath::parse(env).directories) path.directories.push_back(std::move(directory));
  return path;
}

void setPackageSearchPath(PackageSearchPath path) {
  std::lock_guard lock(searchPathMutex);
  configuredSearchPath = std::move(path);
}

std::filesystem::path resolveResourcePath(const std::string& reference, const std::filesystem::path& referencingFile,
                                          const std::string& field) {
  if (reference.empty()) throw InputError(referencingFile.string(), field, "expected a file path, got an empty string");
  if (startsWith(reference, kPackagePrefix)) return resolvePackage(reference, referencingFile, field);
  if (!startsWith(reference, kFilePrefix) && reference.find("://") != std::string::npos)
    throw InputError(
        referencingFile.string(), field,
        "'" + reference + "' is not a URI this reads: expected package://NAME/path, file:///path or a file path");
  std::filesystem::path path =
      startsWith(reference, kFilePrefix) ? reference.substr(std::string(kFilePrefix).size()) : reference;
  if (path.is_relative()) path = std::filesystem::absolute(referencingFile).parent_path() / path;
  path = path.lexically_normal();
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw InputError(referencingFile.string(), field,
                     "'" + reference + "' is " + path.string() + ", which does not exist");
  return path;
}

}  // namespace pmdplan
