#pragma once
// The processes of one benchmark campaign: a single process, or the ranks `mpirun -np P` started.
// MPI is initialised only when an MPI launcher started this process (its environment says so),
// so a plain `pmdplan bench` never depends on an MPI runtime. A build without MPI refuses to run
// under a launcher with more than one rank instead of running the campaign P times.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace pmdplan {

class CampaignRanks {
 public:
  /// Throws InputError (field "mpirun") when launched with several ranks by a build without MPI.
  CampaignRanks();
  ~CampaignRanks();
  CampaignRanks(const CampaignRanks&) = delete;
  CampaignRanks& operator=(const CampaignRanks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool first() const { return rank_ == 0; }

  /// The campaign's next job index, shared by all ranks: the calls of all ranks together return
  /// 0, 1, 2, … each once (an atomic counter on rank 0, MPI_Fetch_and_op). A rank takes a job when
  /// it has finished the last, so ranks whose runs happen to be long (runs at the time limit) take
  /// fewer and no rank waits for another at the end (a fixed split left one rank with most of the
  /// long runs: docs/benchmarks.md, the speed-up of mpirun).
  std::size_t takeJob();

  /// Every rank passes its text; rank 0 gets all of them in rank order, the others get nothing.
  std::vector<std::string> gatherToFirst(const std::string& mine) const;

 private:
  struct SharedCounter;  ///< the MPI window of takeJob
  int rank_ = 0;
  int size_ = 1;
  bool initialisedMpi_ = false;
  std::size_t nextJob_ = 0;  ///< takeJob's counter in a single process
  std::unique_ptr<SharedCounter> counter_;
};

/// The rank count an MPI launcher announced in the environment (OpenMPI's OMPI_COMM_WORLD_SIZE,
/// MPICH's PMI_SIZE), or 1 when not launched by one.
int launcherRankCount();

}  // namespace pmdplan
