#pragma once
// The self-contained viewer folder `pmdplan view` writes: the page and its script bundle (copied
// from the viewer's build output), the data as a script (viewer-data.js, so the page also works
// opened straight from the disk, where browsers refuse to fetch files), and mesh files.
#include <filesystem>
#include <vector>

#include "pmdplan/io/viewer/viewer_data.hpp"

namespace pmdplan {

/// The files every viewer folder gets from the viewer's build output.
const std::vector<std::string>& viewerAssetFiles();

/// Where the built viewer (viewerAssetFiles()) is: $PMDPLAN_VIEWER_DIR if set, else viewer/dist
/// beside the data directory (a source tree), else viewer/ beside it (an installation:
/// share/pmdplan/viewer). Throws std::runtime_error saying how to build it if none holds them.
std::filesystem::path viewerAssetDirectory();

/// Whether `file` may go into a viewer folder as a robot's visual mesh: a regular file with an
/// extension the viewer draws (.stl, .obj, .dae) that passes the mesh reader's checks
/// (model/mesh_file.hpp: size, structure, triangles). A URDF's <visual> may name any file
/// (file:///etc/shadow); only a mesh is copied, and the viewer draws the link's collision geometry
/// in place of one that is not.
bool isViewerMeshFile(const std::filesystem::path& file);

/// Writes the folder (created if missing; files of an earlier viewer in it are replaced, others
/// left alone) and returns the files written. A copied file (a mesh) never gets more permission
/// bits than its source has: a mesh readable only by its owner stays so in the folder. The data goes in as
/// `window.pmdplanViewerData = {...};`, in the deterministic JSON form of formatJson().
std::vector<std::filesystem::path> writeViewerFolder(const std::filesystem::path& directory, const ViewerData& data,
                                                     const std::filesystem::path& assetDirectory);

}  // namespace pmdplan
