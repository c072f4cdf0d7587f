#include "pmdplan/io/viewer/viewer_folder_outputs.hpp"

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/io/viewer/viewer_folder.hpp"

namespace pmdplan {
namespace {

void checkViewerFolderFile(const std::filesystem::path& target, const std::filesystem::path& source,
                           const std::string& option) {
  std::error_code error;
  if (std::filesystem::is_directory(target.parent_path(), error))
    checkOutputPath(target, option, {source});
  else
    checkOutputNameLength(target, option);
}

}  // namespace

void checkViewerFolderOutputs(const std::filesystem::path& directory, const ViewerData& data,
                              const std::filesystem::path& assetDirectory, const std::string& option) {
  for (const auto& file : viewerAssetFiles()) checkViewerFolderFile(directory / file, assetDirectory / file, option);
  for (const ViewerFolderFile& file : data.files)
    checkViewerFolderFile(directory / file.relativePath, file.source, option);
  checkViewerFolderFile(directory / "viewer-data.js", {}, option);
}

}  // namespace pmdplan
