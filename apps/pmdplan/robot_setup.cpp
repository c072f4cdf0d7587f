#include "robot_setup.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <sstream>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan::cli {

RobotModel loadWithCompanionText(const std::filesystem::path& urdf, const std::string& companionText) {
  // A private folder (mkdtemp: a fresh name, mode 0700), so that no one else can put a symbolic
  // link where the scratch file goes.
  std::error_code error;
  std::string folder = (std::filesystem::temp_directory_path(error) / "pmdplan-groups-XXXXXX").string();
  if (error) throw InputError("", "TMPDIR", "no folder for scratch files: " + error.message());
  if (!::mkdtemp(folder.data()))
    throw InputError(folder, "", std::string("cannot create a scratch folder: ") + std::strerror(errno));
  const auto scratch = std::filesystem::path(folder) / "groups.srdf";
  try {
    writeFileAtomically(scratch, companionText);
    RobotModel model = RobotModel::load(urdf, scratch);
    std::filesystem::remove_all(folder, error);
    return model;
  } catch (...) {
    std::filesystem::remove_all(folder, error);
    throw;
  }
}

Configuration homeConfiguration(const RobotModel& model, const std::string& text) {
  Configuration home(model.dof());
  for (int i = 0; i < model.dof(); ++i) {
    const auto& joint = model.activeJoints()[static_cast<std::size_t>(i)];
    home[i] = std::clamp(0.0, joint.lower, joint.upper);
  }
  std::stringstream in(text);
  std::string entry;
  while (std::getline(in, entry, ',')) {
    if (entry.empty()) continue;
    const auto equals = entry.find('=');
    const std::string name = entry.substr(0, equals);
    const int index = model.activeIndex(name);
    if (equals == std::string::npos || index < 0)
      throw InputError(
          "", "--home",
          "'" + entry + "': expected ACTIVE_JOINT=DEGREES[,...] naming active joints of " + model.urdfPath().string());
    double value = 0.0;
    try {
      std::size_t used = 0;
      value = std::stod(entry.substr(equals + 1), &used);
      if (used != entry.size() - equals - 1) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
      throw InputError("", "--home", "'" + entry + "': expected a number of degrees after '='");
    }
    // stod reads "nan" and "inf": a NaN passed the limits test below and changed which pairs the
    // sampling skipped.
    if (!std::isfinite(value))
      throw InputError("", "--home", "'" + entry + "': expected a finite number of degrees for joint " + name);
    const auto& joint = model.activeJoints()[static_cast<std::size_t>(index)];
    const bool prismatic =
        model.joints()[static_cast<std::size_t>(model.jointIndex(name))].type == JointType::Prismatic;
    home[index] = prismatic ? value : value * std::numbers::pi / 180.0;
    if (home[index] < joint.lower - 1e-9 || home[index] > joint.upper + 1e-9)
      throw InputError("", "--home", "'" + entry + "' is outside the joint's limits");
    home[index] = std::clamp(home[index], joint.lower, joint.upper);
  }
  return home;
}

std::string robotInitHint(const std::filesystem::path& urdf) {
  return "`pmdplan robot init " + urdf.string() + " --arm J1,J2,... --palm LINK [--hand J1,...]`";
}

}  // namespace pmdplan::cli
