// 13,500 glove frames -> synergy model (issue 3: under a second on one core). The recording is the
// synthetic operator's, seed 1, as text, so the timed path is the real one: parse the CSV,
// calibrate, map to the SAH joints (clamping), PCA.
#include <benchmark/benchmark.h>

#include "pmdplan/glove/glove_calibration_file.hpp"
#include "pmdplan/glove/glove_csv.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/synergy/hand_mapping_file.hpp"
#include "pmdplan/synergy/recording_analysis.hpp"
#include "pmdplan/synergy/synthetic_operator.hpp"

namespace {

using namespace pmdplan;

struct PaperSizedSession {
  JointLimits hand;
  HandMapping mapping;
  std::string csv;
  GloveRecording recording;
  GloveCalibration calibration;

  PaperSizedSession() {
    const RobotModel robot = RobotModel::loadBuiltIn("sah_tx90");
    for (const int index : robot.group("hand")) hand.push_back(robot.activeJoints()[static_cast<std::size_t>(index)]);
    mapping = loadHandMapping(std::string(PMDPLAN_TEST_DATA_DIR) + "/glove/cyberglove22_to_sah.yaml");
    const SyntheticGloveSession session = synthesiseGloveSession(SyntheticOperatorSettings{}, mapping, hand);
    csv = formatGloveCsv(session.recording);
    recording = session.recording;
    calibration = session.calibration;
  }
};

const PaperSizedSession& session() {
  static const PaperSizedSession instance;
  return instance;
}

void reportModel(benchmark::State& state, const RecordingAnalysis& analysis) {
  state.counters["frames"] = analysis.fit.frames;
  state.counters["frames_per_s"] =
      benchmark::Counter(analysis.fit.frames, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["cum1_pct"] = 100 * analysis.fit.cumulativeVariance(0);
  state.counters["cum2_pct"] = 100 * analysis.fit.cumulativeVariance(1);
  state.counters["cum3_pct"] = 100 * analysis.fit.cumulativeVariance(2);
  state.counters["clamped"] = static_cast<double>(analysis.clampedValues);
}

/// CSV text of 13,500 frames -> synergy model: the whole path a user's recording takes.
void BM_CsvRecordingToSynergyModel(benchmark::State& state) {
  const auto& s = session();
  RecordingAnalysis analysis;
  for (auto _ : state) {
    const GloveRecording recording = parseGloveCsv(s.csv, "synthetic.csv");
    analysis =
        analyseRecording(recording, s.calibration, s.mapping, s.hand, SynergyFitSettings{{"thumb_base"}}, "bench");
    benchmark::DoNotOptimize(analysis.fit.model.directions.data());
  }
  reportModel(state, analysis);
}
BENCHMARK(BM_CsvRecordingToSynergyModel)->Unit(benchmark::kMillisecond);

/// Frames already in memory -> synergy model: calibrate, map, PCA.
void BM_FramesToSynergyModel(benchmark::State& state) {
  const auto& s = session();
  RecordingAnalysis analysis;
  for (auto _ : state) {
    analysis =
        analyseRecording(s.recording, s.calibration, s.mapping, s.hand, SynergyFitSettings{{"thumb_base"}}, "bench");
    benchmark::DoNotOptimize(analysis.fit.model.directions.data());
  }
  reportModel(state, analysis);
}
BENCHMARK(BM_FramesToSynergyModel)->Unit(benchmark::kMillisecond);

/// The synthetic operator itself (13,500 frames, seed 1), for reference.
void BM_SyntheticOperator(benchmark::State& state) {
  const auto& s = session();
  for (auto _ : state) {
    const SyntheticGloveSession generated = synthesiseGloveSession(SyntheticOperatorSettings{}, s.mapping, s.hand);
    benchmark::DoNotOptimize(generated.recording.frames.data());
  }
  state.counters["frames"] = SyntheticOperatorSettings{}.frames;
}
BENCHMARK(BM_SyntheticOperator)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
