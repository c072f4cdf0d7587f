#include "pmdplan/bench/campaign_journal.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "bench/record_samples.hpp"
#include "pmdplan/core/input_error.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

TEST(CampaignJournal, KeepsRecordsAcrossRanksAndReopenings) {
  test::TempDir dir;
  BenchSettings options;
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
  BenchSettings options;
  { CampaignJournal(dir.path() / "j", options, 0).append(0, test::successfulRun("can_on_table", "pmd", 0, 0.25)); }
  BenchSettings other = options;
  other.runs = 11;
  try {
    CampaignJournal(dir.path() / "j", other, 0);
    ADD_FAILURE() << "accepted another campaign's journal";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "--journal");
    EXPECT_EQ(error.file(), (dir.path() / "j" / "rank0.jsonl").string());
  }
  std::ofstream(dir.path() / "j" / "rank0.jsonl", std::ios::app) << "not a record\n";
  test::expectInputError([&] { CampaignJournal(dir.path() / "j", options, 0); },
                         (dir.path() / "j" / "rank0.jsonl").string(), "line 3", "expected one finished run");
}

TEST(CampaignJournal, LinesAreJsonObjectsOfTheJobAndItsRecord) {
  test::TempDir dir;
  BenchSettings options;
  const RunRecord a = test::successfulRun("can_on_table", "pmd", 0, 0.25);
  { CampaignJournal(dir.path() / "j", options, 0).append(7, a); }
  std::ifstream in(dir.path() / "j" / "rank0.jsonl");
  std::string header, line;
  std::getline(in, header), std::getline(in, line);
  EXPECT_EQ(header, CampaignJournal::header(options));
  EXPECT_EQ(nlohmann::json::parse(header).at("pmdplan_bench_journal"), 1);
  const nlohmann::json json = nlohmann::json::parse(line);
  EXPECT_EQ(json.at("job"), 7);
  EXPECT_EQ(json.at("task"), "can_on_table");
  EXPECT_EQ(json.size(), runRecordKeys().size() + 1);
}

// A folder (or anything but a regular file) named like a rank's file is the user's mistake: refused
// naming it, by every rank (it was exit 3 for the rank whose file it is, skipped by the others).
TEST(CampaignJournal, AFolderNamedLikeARankFileIsRefusedNamingIt) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "j" / "rank1.jsonl");
  for (const int rank : {0, 1})
    test::expectInputError([&] { CampaignJournal(dir.path() / "j", BenchSettings{}, rank); },
                           (dir.path() / "j" / "rank1.jsonl").string(), "--journal", "is not a regular file");
  test::expectInputError([&] { CampaignJournal::finishedJobs(dir.path() / "j", BenchSettings{}); },
                         (dir.path() / "j" / "rank1.jsonl").string(), "--journal", "is not a regular file");
}

// nlohmann keeps the last of a repeated key: a line saying "job" twice is refused, naming the key.
TEST(CampaignJournal, ALineWithARepeatedKeyIsRefused) {
  test::TempDir dir;
  BenchSettings options;
  { CampaignJournal(dir.path() / "j", options, 0).append(3, test::successfulRun("can_on_table", "pmd", 0, 0.25)); }
  const auto file = dir.path() / "j" / "rank0.jsonl";
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.insert(text.rfind("{\"job\"") + 1, "\"job\": 5, ");
  dir.write("j/rank0.jsonl", text);
  test::expectInputError([&] { CampaignJournal(dir.path() / "j", options, 0); }, file.string(), "line 2, job",
                         "given twice in one object");
}

// The first line of a rank file is not shown: another campaign's is described by the setting that
// differs, anything else by its length.
TEST(CampaignJournal, ItsFirstLineIsDescribedNotShown) {
  test::TempDir dir;
  BenchSettings options;
  { CampaignJournal(dir.path() / "j", options, 0); }
  BenchSettings other = options;
  other.runs = 11;
  test::expectInputError([&] { CampaignJournal(dir.path() / "j", other, 0); },
                         (dir.path() / "j" / "rank0.jsonl").string(), "--journal",
                         "belongs to another campaign (its runs is '" + std::to_string(options.runs) + "')");
  const std::string secret = "root:$6$saltsalt$" + std::string(86, 'h') + ":19000:0:99999:7:::";
  dir.write("j/rank0.jsonl", secret + "\n\x1b[2J\n");
  try {
    CampaignJournal(dir.path() / "j", options, 0);
    ADD_FAILURE() << "accepted a file that is not a journal";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).find("saltsalt"), std::string::npos) << error.what();
    EXPECT_THAT(error.message(), ::testing::HasSubstr("its first line is a text of 122 characters"));
  }
}

// A journal of the tab-separated format before JSON lines is refused naming the file and line 1.
TEST(CampaignJournal, AnOldTabSeparatedJournalIsAnError) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "j");
  std::ofstream(dir.path() / "j" / "rank0.tsv") << "# pmdplan bench journal: tasks=can_on_table\n0\trun-record-2\n";
  test::expectInputError([&] { CampaignJournal(dir.path() / "j", BenchSettings{}, 0); },
                         (dir.path() / "j" / "rank0.tsv").string(), "line 1", "older pmdplan");
}

}  // namespace
}  // namespace pmdplan
