#include "pmdplan/bench/campaign_journal.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "bench/record_samples.hpp"
#include "pmdplan/core/input_error.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

TEST(CampaignJournal, KeepsRecordsAcrossRanksAndReopenings) {
  test::TempDir dir;
  BenchOptions options;
  const RunRecord a = test::successfulRun("can_on_table", "pmd", 0, 0.25),
                  b = test::failedRun("can_on_table", "pmd", 1, "not solved: time limit");
  {
    CampaignJournal rank0(dir.path() / "j", options, 0), rank1(dir.path() / "j", options, 1);
    rank0.append(0, a);
    rank1.append(1, b);
  }
  const CampaignJournal reopened(dir.path() / "j", options, 0);
  EXPECT_EQ(reopened.recordCount(), 2u);
  ASSERT_NE(reopened.find(1), nullptr);
  EXPECT_EQ(encodeRunRecord(*reopened.find(1)), encodeRunRecord(b));
  EXPECT_EQ(encodeRunRecord(*reopened.find(0)), encodeRunRecord(a));
  EXPECT_EQ(reopened.find(2), nullptr);
}

TEST(CampaignJournal, AnotherCampaignsFileOrAGarbledLineIsAnError) {
  test::TempDir dir;
  BenchOptions options;
  { CampaignJournal(dir.path() / "j", options, 0).append(0, test::successfulRun("can_on_table", "pmd", 0, 0.25)); }
  BenchOptions other = options;
  other.runs = 11;
  try {
    CampaignJournal(dir.path() / "j", other, 0);
    ADD_FAILURE() << "accepted another campaign's journal";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "--journal");
    EXPECT_EQ(error.file(), (dir.path() / "j" / "rank0.tsv").string());
  }
  std::ofstream(dir.path() / "j" / "rank0.tsv", std::ios::app) << "not a record\n";
  EXPECT_THROW(CampaignJournal(dir.path() / "j", options, 0), InputError);
}

}  // namespace
}  // namespace pmdplan
