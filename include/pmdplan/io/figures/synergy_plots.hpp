#pragma once
// The paper's synergy figures as SVG files a person can open in any browser: the variance each
// PMD carries with the cumulative total (Fig. 10), and scatter plots of the Fig. 7 joint pairs.
// Plain SVG text, written here, so no plotting library is needed; the same data gives the same
// bytes.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

struct SynergyPlotSettings {
  /// Most frames drawn per scatter plot (evenly spaced through the recording): a 13,500-frame
  /// recording drawn whole gives files of megabytes and no clearer picture.
  int maxScatterPoints = 3000;
};

/// Fig. 10: bars of each PMD's share of the variance and the line of the cumulative share, in
/// percent, with the paper's 42.19 / 77.12 / 84.71 % for 1, 2, 3 PMDs marked for comparison.
std::string cumulativeVarianceSvg(const SynergyModel& model);

/// Fig. 7: one panel per pair of figure7JointPairs() whose joints are both in `joints`, joint
/// values in degrees over the joints' limits, each with its correlation r (also in the paper's
/// sign convention) and the paper's finding. `postures`: one row per frame, one column per joint
/// (rad). Throws std::invalid_argument if the sizes disagree.
std::string jointPairsSvg(const Eigen::MatrixXd& postures, const JointLimits& joints,
                          const SynergyPlotSettings& options = {});

/// Writes cumulative_variance.svg and (if `postures` has rows) joint_pairs.svg into `directory`
/// (created if missing) and returns the files written.
std::vector<std::filesystem::path> writeSynergyPlots(const std::filesystem::path& directory, const SynergyModel& model,
                                                     const Eigen::MatrixXd& postures, const JointLimits& joints,
                                                     const SynergyPlotSettings& options = {});

}  // namespace pmdplan
