#include "pmdplan/bench/results_csv.hpp"

#include <charconv>

#include "pmdplan/text/csv_field.hpp"

namespace pmdplan {
namespace {

std::string number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

const std::vector<std::string>& timingCsvColumns() {
  static const std::vector<std::string> columns = {"planning_time_s", "smoothing_time_s", "certification_time_s"};
  return columns;
}

std::string runRecordsCsv(const std::vector<RunRecord>& records) {
  std::string csv =
      "task,planner,run,seed,solved,planning_time_s,smoothing_time_s,certification_time_s,valid,samples,arm_trials,max_"
      "trials,final_rho_a,"
      "nodes_by_hand_dimension,roadmap_nodes,path_nodes,path_length,"
      "collision_checks,subspace_distance_mean,subspace_distance_max,mahalanobis_mean,authors_pmd_distance_mean,"
      "authors_pmd_distance_max,joint_coupling,failure\n";
  for (const RunRecord& r : records) {
    const bool hasPath = r.solved;
    const IndependentHumanLikeness* independent =
        r.humanLikeness && r.humanLikeness->independent ? &*r.humanLikeness->independent : nullptr;
    csv += csvField(r.task) + "," + csvField(r.planner) + "," + std::to_string(r.run) + "," + std::to_string(r.seed) +
           "," + (r.solved ? "1" : "0") + "," + number(r.planningTimeSeconds) + "," + number(r.smoothingTimeSeconds) +
           "," + number(r.certificationTimeSeconds) + "," + (r.valid ? "1" : "0") + "," + std::to_string(r.samples) +
           "," + std::to_string(r.armTrials) + "," + std::to_string(r.maxTrials) + "," + number(r.finalArmHalfSize) +
           "," + csvField(nodesByHandDimensionText(r.nodesByHandDimension)) + "," + std::to_string(r.roadmapNodes) +
           "," + (hasPath ? std::to_string(r.pathNodes) : "") + "," + (hasPath ? number(r.pathLength) : "") + "," +
           std::to_string(r.collisionChecks) + "," +
           (r.humanLikeness ? number(r.humanLikeness->subspaceDistanceMean) : "") + "," +
           (r.humanLikeness ? number(r.humanLikeness->subspaceDistanceMax) : "") + "," +
           (r.humanLikeness ? number(r.humanLikeness->mahalanobisMean) : "") + "," +
           (independent ? number(independent->authorsSubspaceDistanceMean) : "") + "," +
           (independent ? number(independent->authorsSubspaceDistanceMax) : "") + "," +
           (independent ? number(independent->jointCoupling) : "") + "," + csvField(r.failure) + "\n";
  }
  return csv;
}

}  // namespace pmdplan
