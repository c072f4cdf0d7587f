// The glove live reaches the page: a pseudo-terminal glove (socat), `pmdplan glove stream --serve`
// and chromium through viewer/test/live_glove_browser_test.mjs, which also prints the latency from
// the serial write to the page. Screenshots and latency.json in build/test-output/live-glove/.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <iostream>

#include "support/run_cli.hpp"

namespace pmdplan {
namespace {

using test::quoted;

using test::kBuildDirectory;
using test::kSourceTree;

TEST(LiveGloveBrowser, APseudoTerminalGloveMovesTheHandOnThePage) {
  ASSERT_TRUE(std::filesystem::exists(kSourceTree / "viewer" / "node_modules" / "playwright-core"))
      << "viewer/node_modules is missing: run scripts/install-deps (npm ci in viewer/)";
  ASSERT_EQ(std::system("command -v socat >/dev/null"), 0) << "socat is missing: run scripts/install-deps";
  const auto work = kBuildDirectory / "test-output" / "live-glove";
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  const auto glove = std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "glove";
  const std::string command = "node " + quoted(kSourceTree / "viewer" / "test" / "live_glove_browser_test.mjs") +
                              " --cli " + quoted(PMDPLAN_CLI_PATH) + " --calibration " +
                              quoted(glove / "synthetic_operator_sample.calibration.yaml") + " --sample " +
                              quoted(glove / "synthetic_operator_sample.csv") + " --work " + quoted(work) + " 2>&1";
  std::cout << "$ " << command << std::endl;
  const int status = std::system(command.c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0);
  EXPECT_TRUE(std::filesystem::is_regular_file(work / "live-glove-frame30.png"));
  EXPECT_TRUE(std::filesystem::is_regular_file(work / "live-glove-frame110.png"));
  EXPECT_TRUE(std::filesystem::is_regular_file(work / "latency.json"));
}

}  // namespace
}  // namespace pmdplan
