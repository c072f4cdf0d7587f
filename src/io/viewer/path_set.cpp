#include "pmdplan/io/viewer/path_set.hpp"

#include <algorithm>
#include <map>
#include <regex>
#include <set>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

using Json = nlohmann::ordered_json;

/// pmd, full, then the other planners by name.
int plannerRank(const std::string& planner) {
  if (planner == "pmd") return 0;
  if (planner == "full") return 1;
  return 2;
}

}  // namespace

ViewInput readViewInput(const std::filesystem::path& file) {
  ViewInput input;
  input.file = file;
  const std::string text = readTextFile(file);
  if (isTrajectoryFileText(text)) {
    input.trajectory = parseTrajectoryFile(text, file.string());
    input.path = trajectoryAsPathFile(*input.trajectory);
  } else {
    input.path = parsePathFile(text, file.string());
  }
  return input;
}

void checkOneTask(const std::vector<ViewInput>& inputs) {
  for (std::size_t i = 1; i < inputs.size(); ++i)
    if (inputs[i].path.task != inputs.front().path.task)
      throw InputError(inputs[i].file.string(), "task",
                       "the path was planned for task '" + inputs[i].path.task + "', but " +
                           inputs.front().file.string() + " for task '" + inputs.front().path.task +
                           "'; expected paths of one task to view together");
}

std::string benchPathFileName(const std::string& task, const std::string& planner, std::uint64_t seed) {
  std::string name = planner;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return c == ':' || c == '/' || c == '.'; }, '-');
  return task + "." + name + ".seed" + std::to_string(seed) + ".path.json";
}

std::vector<std::filesystem::path> benchSeedPaths(const std::filesystem::path& folder, std::uint64_t seed) {
  static const std::regex name(R"((.+)\.([^.]+)\.seed([0-9]+)\.path\.json)");
  struct Found {
    int rank;
    std::string planner;
    std::filesystem::path file;
  };
  std::vector<Found> found;
  std::set<std::uint64_t> seeds;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    std::smatch match;
    const std::string file = entry.path().filename().string();
    if (!entry.is_regular_file() || !std::regex_match(file, match, name)) continue;
    const std::uint64_t fileSeed = std::stoull(match[3].str());
    seeds.insert(fileSeed);
    if (fileSeed == seed)
      found.push_back({plannerRank(match[2].str()), match[2].str() + "/" + match[1].str(), entry.path()});
  }
  if (found.empty()) {
    std::string there;
    for (const std::uint64_t s : seeds) there += (there.empty() ? "" : ", ") + std::to_string(s);
    throw InputError(folder.string(), "--seed",
                     "no path file of seed " + std::to_string(seed) + " (TASK.PLANNER.seed" + std::to_string(seed) +
                         ".path.json, written by pmdplan bench --paths); " +
                         (there.empty() ? "the folder holds none" : "seeds there: " + there));
  }
  std::sort(found.begin(), found.end(),
            [](const Found& a, const Found& b) { return a.rank != b.rank ? a.rank < b.rank : a.planner < b.planner; });
  std::vector<std::filesystem::path> files;
  for (const Found& f : found) files.push_back(f.file);
  return files;
}

std::string viewPathName(const ViewInput& input) {
  return input.path.planner + ", seed " + std::to_string(input.path.seed) + (input.trajectory ? ", timed" : "") + " (" +
         input.file.filename().string() + ")";
}

void addOverlayPaths(ViewerData& data, const Task& task, const std::vector<ViewInput>& inputs,
                     const ViewerDataSettings& parameters) {
  if (inputs.size() < 2) return;
  Json& document = data.document;
  const auto prefixed = [](const ViewInput& input, const std::string& warning) {
    return input.file.filename().string() + ": " + warning;
  };
  Json warnings = Json::array();
  for (const auto& warning : document["warnings"])
    warnings.push_back(prefixed(inputs.front(), warning.get<std::string>()));
  document["path"]["name"] = viewPathName(inputs.front());
  document["path"]["file"] = inputs.front().file.filename().string();
  std::string planners = inputs.front().path.planner;
  Json overlays = Json::array();
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    ViewerDataSettings own = parameters;
    own.trajectory = inputs[i].trajectory ? &*inputs[i].trajectory : nullptr;
    ViewerPath path = viewerPath(task, inputs[i].path, inputs[i].file, own);
    path.json["name"] = viewPathName(inputs[i]);
    path.json["file"] = inputs[i].file.filename().string();
    overlays.push_back(std::move(path.json));
    for (const std::string& warning : path.warnings) warnings.push_back(prefixed(inputs[i], warning));
    planners += ", " + inputs[i].path.planner;
  }
  document["title"] = task.name + " - " + std::to_string(inputs.size()) + " paths: " + planners;
  document["overlay_paths"] = std::move(overlays);
  document["warnings"] = std::move(warnings);
}

}  // namespace pmdplan
