#include "pmdplan/io/viewer/viewer_folder.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/json_text.hpp"
#include "pmdplan/model/mesh_file.hpp"

namespace pmdplan {
namespace {

bool holdsAssets(const std::filesystem::path& directory) {
  for (const auto& file : viewerAssetFiles())
    if (!std::filesystem::is_regular_file(directory / file)) return false;
  return true;
}

/// Makes `target` carry at most the permission bits of `source` before it is written, so that the
/// write (which keeps the mode of a file it replaces, core/atomic_file.hpp) never widens them: an
/// existing copy loses the bits the source lacks, a new one is created empty with the source's
/// bits (less the umask). Returns whether it created the file.
bool narrowCopyMode(const std::filesystem::path& source, const std::filesystem::path& target) {
  struct stat from {};
  if (::stat(source.c_str(), &from) != 0) return false;  // the read that follows names the problem
  const mode_t allowed = from.st_mode & 0666;
  struct stat existing {};
  if (::stat(target.c_str(), &existing) == 0) {
    if (S_ISREG(existing.st_mode) && (existing.st_mode & 0777 & ~allowed) != 0)
      ::chmod(target.c_str(), existing.st_mode & allowed);
    return false;
  }
  const int fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, allowed);
  if (fd < 0) return false;  // the write that follows names the problem
  ::close(fd);
  return true;
}

}  // namespace

bool isViewerMeshFile(const std::filesystem::path& file) {
  if (!hasMeshFileExtension(file)) return false;
  try {
    readMeshFile(file, Eigen::Vector3d::Ones());  // a regular file first (stat), then its bounds
  } catch (const InputError&) {
    return false;
  }
  return true;
}

const std::vector<std::string>& viewerAssetFiles() {
  static const std::vector<std::string> files{"index.html", "viewer.css", "pmdplan-viewer.js",
                                              "THIRD_PARTY_NOTICES.txt"};
  return files;
}

std::filesystem::path viewerAssetDirectory() {
  if (const char* env = std::getenv("PMDPLAN_VIEWER_DIR"); env && *env) {
    if (!holdsAssets(env))
      throw std::runtime_error(std::string("PMDPLAN_VIEWER_DIR=") + env +
                               " does not hold the built viewer (index.html, pmdplan-viewer.js, ...)");
    return env;
  }
  const std::filesystem::path data = dataDirectory();
  for (const auto& candidate : {data.parent_path() / "viewer" / "dist", data.parent_path() / "viewer"})
    if (holdsAssets(candidate)) return candidate;
  throw std::runtime_error("the built web viewer is missing (looked in " +
                           (data.parent_path() / "viewer" / "dist").string() +
                           "); build it with: npm --prefix viewer ci && npm --prefix viewer run build");
}

std::vector<std::filesystem::path> writeViewerFolder(const std::filesystem::path& directory, const ViewerData& data,
                                                     const std::filesystem::path& assetDirectory) {
  createOutputFolder(directory, "--out");
  std::vector<std::filesystem::path> written;
  for (const auto& file : viewerAssetFiles()) {
    writeFileAtomically(directory / file, readTextFile(assetDirectory / file));
    written.push_back(directory / file);
  }
  for (const ViewerFolderFile& file : data.files) {
    const auto target = directory / file.relativePath;
    createOutputFolder(target.parent_path(), "--out");
    const bool created = narrowCopyMode(file.source, target);
    try {
      writeFileAtomically(target, readTextFile(file.source));
    } catch (...) {
      if (created) std::filesystem::remove(target);
      throw;
    }
    written.push_back(target);
  }
  const auto dataFile = directory / "viewer-data.js";
  std::string json = formatJson(data.document);
  if (!json.empty() && json.back() == '\n') json.pop_back();
  writeFileAtomically(dataFile, "window.pmdplanViewerData = " + json + ";\n");
  written.push_back(dataFile);
  return written;
}

}  // namespace pmdplan
