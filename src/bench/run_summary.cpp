#include "pmdplan/bench/run_summary.hpp"

#include <algorithm>
#include <functional>
#include <numeric>

namespace pmdplan {

MetricSummary summariseValues(std::vector<double> values) {
  MetricSummary summary;
  summary.count = values.size();
  if (values.empty()) return summary;
  summary.mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  summary.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  return summary;
}

RunSummary summariseRuns(const std::vector<RunRecord>& records, const std::string& task, const std::string& planner) {
  RunSummary s;
  s.task = task;
  s.planner = planner;
  std::vector<const RunRecord*> successes;
  for (const RunRecord& r : records) {
    if (r.task != task || r.planner != planner) continue;
    ++s.runs;
    s.solved += r.solved;
    if (r.succeeded()) {
      ++s.succeeded;
      successes.push_back(&r);
    }
  }
  const auto metric = [&](const std::function<double(const RunRecord&)>& value) {
    std::vector<double> values;
    for (const RunRecord* r : successes) values.push_back(value(*r));
    return summariseValues(values);
  };
  s.planningTime = metric([](const RunRecord& r) { return r.planningTimeSeconds; });
  s.smoothingTime = metric([](const RunRecord& r) { return r.smoothingTimeSeconds; });
  s.certificationTime = metric([](const RunRecord& r) { return r.certificationTimeSeconds; });
  s.samples = metric([](const RunRecord& r) { return static_cast<double>(r.samples); });
  s.armTrials = metric([](const RunRecord& r) { return static_cast<double>(r.armTrials); });
  s.maxTrials = metric([](const RunRecord& r) { return static_cast<double>(r.maxTrials); });
  s.finalArmHalfSize = metric([](const RunRecord& r) { return r.finalArmHalfSize; });
  s.roadmapNodes = metric([](const RunRecord& r) { return static_cast<double>(r.roadmapNodes); });
  std::map<int, std::vector<double>> shares;  // every dimension any run used, 0 % where a run did not
  for (const RunRecord* r : successes)
    for (const auto& entry : r->nodesByHandDimension) shares[entry.first];
  for (const RunRecord* r : successes) {
    double sampled = 0.0;
    for (const auto& entry : r->nodesByHandDimension) sampled += static_cast<double>(entry.second);
    if (sampled == 0.0) continue;
    for (auto& [dimension, values] : shares) {
      const auto at = r->nodesByHandDimension.find(dimension);
      values.push_back(at == r->nodesByHandDimension.end() ? 0.0 : 100.0 * static_cast<double>(at->second) / sampled);
    }
  }
  for (auto& [dimension, values] : shares) s.nodeShareByHandDimension[dimension] = summariseValues(values);
  s.pathNodes = metric([](const RunRecord& r) { return static_cast<double>(r.pathNodes); });
  s.pathLength = metric([](const RunRecord& r) { return r.pathLength; });
  s.collisionChecks = metric([](const RunRecord& r) { return static_cast<double>(r.collisionChecks); });
  s.subspaceDistanceMean =
      metric([](const RunRecord& r) { return r.humanLikeness ? r.humanLikeness->subspaceDistanceMean : 0.0; });
  s.subspaceDistanceMax =
      metric([](const RunRecord& r) { return r.humanLikeness ? r.humanLikeness->subspaceDistanceMax : 0.0; });
  s.mahalanobisMean =
      metric([](const RunRecord& r) { return r.humanLikeness ? r.humanLikeness->mahalanobisMean : 0.0; });
  const auto independentMetric = [&](double IndependentHumanLikeness::*field) {
    std::vector<double> values;
    for (const RunRecord* r : successes)
      if (r->humanLikeness && r->humanLikeness->independent) values.push_back(*r->humanLikeness->independent.*field);
    return summariseValues(values);
  };
  s.authorsSubspaceDistanceMean = independentMetric(&IndependentHumanLikeness::authorsSubspaceDistanceMean);
  s.authorsSubspaceDistanceMax = independentMetric(&IndependentHumanLikeness::authorsSubspaceDistanceMax);
  s.jointCoupling = independentMetric(&IndependentHumanLikeness::jointCoupling);
  return s;
}

}  // namespace pmdplan
