#include "pmdplan/io/viewer/viewer_folder.hpp"

#include <cstdlib>
#include <stdexcept>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/io/files/json_text.hpp"

namespace pmdplan {
namespace {

bool holdsAssets(const std::filesystem::path& directory) {
  for (const auto& file : viewerAssetFiles())
    if (!std::filesystem::is_regular_file(directory / file)) return false;
  return true;
}

}  // namespace

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
    writeFileAtomically(target, readTextFile(file.source));
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
