// Bounds on work and on option values, refused up front with exit 2 and one line naming the option
// or the file: `time`'s timing options and trajectory samples, `glove stream --replay`'s times and
// speed, `validate`'s states, `robot init --home`, and CLI11's parse errors in pmdplan's one form.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::quoted;
using test::runCli;

const std::filesystem::path kDataDir = PMDPLAN_TEST_DATA_DIR;

/// Runs `arguments` under `timeout 20` (a hang is a failure, not a stuck suite) and expects exit
/// 2 within 10 s, one line on stderr in the documented form, naming every `expected` text.
void expectRefused(const test::TempDir& dir, const std::string& arguments, const std::vector<std::string>& expected) {
  const auto out = dir.path() / "out.txt";
  const auto err = dir.path() / "err.txt";
  const auto began = std::chrono::steady_clock::now();
  const int status = std::system(("timeout 20 " + quoted(PMDPLAN_CLI_PATH) + " " + arguments + " >" + quoted(out) +
                                  " 2>" + quoted(err) + " </dev/null")
                                     .c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  const std::string text = test::contents(err);
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2) << arguments << "\n" << text;
  EXPECT_EQ(text.rfind("pmdplan: error: ", 0), 0u) << arguments << "\n" << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << arguments << "\n" << text;
  for (const auto& part : expected) EXPECT_NE(text.find(part), std::string::npos) << arguments << "\n" << text;
  EXPECT_LT(seconds, 10.0) << arguments;
}

using test::plannedPath;

TEST(WorkBoundsCli, TimingOptionsOutOfRangeAreRefusedBeforeAnyWork) {
  test::TempDir dir;
  const std::string path = quoted(plannedPath(dir)) + " -o " + quoted(dir.path() / "t.json");
  // Each of these exited 0 with a wrong trajectory, ate 23 GB, failed with bad_alloc or never ended.
  expectRefused(dir, "time " + path + " --blend-tolerance 1e-20", {"--blend-tolerance", "0.001 to 1"});
  expectRefused(dir, "time " + path + " --blend-tolerance 1e-12", {"--blend-tolerance", "0.001 to 1"});
  expectRefused(dir, "time " + path + " --sample-interval 1e-300", {"--sample-interval", "0.0001 to 1"});
  expectRefused(dir, "time " + path + " --sample-interval 1e-9", {"--sample-interval", "0.0001 to 1"});
  expectRefused(dir, "time " + path + " --velocity-scale 1e-6", {"--velocity-scale", "0.01 to 1"});
  expectRefused(dir, "time " + path + " --acceleration-scale 0", {"--acceleration-scale", "0.01 to 1"});
  // In range, but 26 s of trajectory every 0.1 ms is 2.6·10⁵ points: more than 10⁵.
  expectRefused(dir, "time " + path + " --velocity-scale 0.01 --acceleration-scale 0.01 --sample-interval 0.0001",
                {"--sample-interval", "more than 100000"});
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "t.json"));
}

TEST(WorkBoundsCli, ATimingLongerThanTheWorkBoundIsRefusedBeforeItStarts) {
  test::TempDir dir;
  const auto planned = plannedPath(dir);
  nlohmann::json document = nlohmann::json::parse(test::contents(planned));
  const auto points = document["points"];
  nlohmann::json longer = nlohmann::json::array({points[0]});
  for (int k = 0; k < 6; ++k) longer.insert(longer.end(), {points[1], points[0]});
  longer.push_back(points[2]);
  document["points"] = longer;
  const auto path = dir.write("long.path.json", document.dump());
  // At 1 % of the limits the path takes about 150 s at rest at every waypoint: more than 100 s.
  expectRefused(dir, "time " + quoted(path) + " --velocity-scale 0.01 --acceleration-scale 0.01",
                {"--velocity-scale", "at most 100 s"});
}

TEST(WorkBoundsCli, AReplayMustKeepItsTimesInOrderAndItsSpeedInRange) {
  test::TempDir dir;
  std::ifstream in(kDataDir / "glove" / "synthetic_operator_sample.csv");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  const auto withTime = [&](const std::string& name, const std::string& time) {
    std::string text;
    int data = 0;
    for (std::string line : lines) {
      if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0])) && ++data == 5)
        line = time + line.substr(line.find(','));
      text += line + "\n";
    }
    std::filesystem::copy_file(kDataDir / "glove" / "synthetic_operator_sample.calibration.yaml",
                               dir.path() / (name + ".calibration.yaml"));
    return dir.write(name + ".csv", text);
  };
  const auto output = " -o " + quoted(dir.path() / "postures.csv");
  // A jump to 1e9 s waited 31 years; a time going back was accepted.
  const auto jump = withTime("jump", "1e9");
  expectRefused(dir, "glove stream --replay " + quoted(jump) + output, {jump.string(), "line 10", "time_s", "60 s"});
  const auto back = withTime("back", "0.001");
  expectRefused(dir, "glove stream --replay " + quoted(back) + output, {back.string(), "line 10", "goes back"});
  const auto sample = quoted(kDataDir / "glove" / "synthetic_operator_sample.csv");
  for (const char* speed : {"1e-18", "1e18", "0.001", "1000"})
    expectRefused(dir, "glove stream --replay " + sample + " --speed " + speed + output, {"--speed", "0.01 to 100"});
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "postures.csv"));
}

TEST(WorkBoundsCli, ValidateRefusesAPathThatNeedsTooManyStatesBeforeCheckingIt) {
  test::TempDir dir;
  nlohmann::json document = nlohmann::json::parse(test::contents(plannedPath(dir)));
  const auto points = document["points"];
  nlohmann::json alternating = nlohmann::json::array({points[0]});
  for (int k = 0; k < 1000; ++k) alternating.insert(alternating.end(), {points[1], points[0]});
  alternating.push_back(points[2]);
  document["points"] = alternating;
  const auto path = dir.write("alternating.path.json", document.dump());
  // 2,001 segments between far configurations: about 5·10⁶ states, minutes of checking.
  expectRefused(dir, "validate can_on_table " + quoted(path),
                {path.string(), "points", "states", "400000", "--tolerance-mm"});
}

TEST(WorkBoundsCli, RobotInitRefusesANonFiniteHomeValueNamingTheJoint) {
  test::TempDir dir;
  const auto urdf = quoted(kDataDir / "robots" / "sah_tx90" / "sah_tx90.urdf");
  for (const char* value : {"nan", "inf", "-inf"})
    expectRefused(dir,
                  "robot init " + urdf + " --palm palm --samples 10 --home tx90_joint_2=" + value + " -o " +
                      quoted(dir.path() / "r.srdf"),
                  {"--home", "tx90_joint_2", "finite"});
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "r.srdf"));
}

TEST(WorkBoundsCli, OptionErrorsAreOneLineInPmdplansForm) {
  test::TempDir dir;
  expectRefused(dir, "time x.json --blend-tolerance abc", {"--blend-tolerance: expected a number, got 'abc'"});
  expectRefused(dir, "plan can_on_table --seed 1 --seed 2", {"--seed: given more than once"});
  expectRefused(dir, "time x.json --task", {"--task: expected a value after it"});
  expectRefused(dir, "time x.json --nope", {"'--nope': not expected by `pmdplan time`"});
  expectRefused(dir, "robot init", {"urdf: required", "pmdplan robot init --help"});
  expectRefused(dir, "", {"command: expected one of", "plan", "validate"});
  // CLI::PositiveNumber printed its range as a 309-digit number.
  expectRefused(dir, "collision-pairs sah_tx90 --samples 0", {"--samples: expected a whole number from 1 to 10000000"});
  const auto help = runCli(dir, "time --help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("--blend-tolerance"), std::string::npos);
}

}  // namespace
}  // namespace pmdplan
