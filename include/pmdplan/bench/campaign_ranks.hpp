#pragma once
// The processes of one benchmark campaign: a single process, or the ranks `mpirun -np P` started.
// MPI is initialised only when an MPI launcher started this process (its environment says so),
// so a plain `pmdplan bench` never depends on an MPI runtime. A build without MPI refuses to run
// under a launcher with more than one rank instead of running the campaign P times.
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

  /// Every rank passes its text; rank 0 gets all of them in rank order, the others get nothing.
  std::vector<std::string> gatherToFirst(const std::string& mine) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  bool initialisedMpi_ = false;
};

/// The rank count an MPI launcher announced in the environment (OpenMPI's OMPI_COMM_WORLD_SIZE,
/// MPICH's PMI_SIZE), or 1 when not launched by one.
int launcherRankCount();

}  // namespace pmdplan
