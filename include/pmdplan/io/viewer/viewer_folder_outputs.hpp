#pragma once
// The up-front check of a viewer folder (`view --out`, `glove stream --out`): every file the folder
// will get is checked as an output before the folder is written, so that none replaces an input
// of the command (a path file, a mesh, the viewer's own build) or another output.
#include <filesystem>
#include <string>

#include "pmdplan/io/viewer/viewer_data.hpp"

namespace pmdplan {

/// Checks the files writeViewerFolder would write into `directory` (field `option`); a folder not
/// there yet holds no input, so its files are checked for their names' length only.
void checkViewerFolderOutputs(const std::filesystem::path& directory, const ViewerData& data,
                              const std::filesystem::path& assetDirectory, const std::string& option);

}  // namespace pmdplan
