#pragma once
// A campaign's finished runs kept on disk as they finish, so a long campaign that is stopped (a
// crash, a killed session, a power cut) resumes where it stopped instead of starting over. The
// journal is a folder; each rank appends to its own file `rank<R>.jsonl` of JSON lines, one per
// finished job ({"job": index, then the keys of its run record, run_record.hpp}, written with one
// append), under a first line that names the campaign (tasks, planners, runs, seed, limits,
// checker, tolerance, synergy model). Reading takes every rank file of the folder, so a campaign
// may resume with another number of ranks; a file of another campaign is an error, and so is a
// journal of an older pmdplan (`rank<R>.tsv`); a half-written last line (the run it belonged to)
// is run again.
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>

#include "pmdplan/bench/bench_options.hpp"
#include "pmdplan/bench/run_record.hpp"

namespace pmdplan {

class CampaignJournal {
 public:
  /// Creates the folder if needed and reads what it holds. Throws InputError (field "--journal")
  /// naming the file if one belongs to another campaign or cannot be read.
  CampaignJournal(const std::filesystem::path& folder, const BenchSettings& options, int rank);

  /// The record of a job finished before, if any.
  const RunRecord* find(std::size_t job) const;
  /// Appends a finished job to this rank's file (flushed before it returns).
  void append(std::size_t job, const RunRecord& record);
  std::size_t recordCount() const { return records_.size(); }

  /// The first line of every file of this campaign's journal.
  static std::string header(const BenchSettings& options);

  /// The finished jobs of the journal in `folder`, read without creating or adding anything (the
  /// report of a campaign still running). Throws InputError like the constructor, and if the
  /// folder does not exist.
  static std::map<std::size_t, RunRecord> finishedJobs(const std::filesystem::path& folder,
                                                       const BenchSettings& options);

 private:
  std::filesystem::path file_;
  std::string header_;
  std::map<std::size_t, RunRecord> records_;
};

}  // namespace pmdplan
