#include "pmdplan/bench/campaign_ranks.hpp"

#include <cstdlib>
#include <numeric>
#include <stdexcept>

#include "pmdplan/core/input_error.hpp"

#ifdef PMDPLAN_WITH_MPI
// The C API only: OpenMPI's and MPICH's mpi.h would pull in their deprecated C++ bindings, which
// live in a library FindMPI's C component does not link.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace pmdplan {

#ifdef PMDPLAN_WITH_MPI
struct CampaignRanks::SharedCounter {
  MPI_Win window = MPI_WIN_NULL;
  long long* value = nullptr;  ///< rank 0's counter, the next job index
};
#else
struct CampaignRanks::SharedCounter {};
#endif

int launcherRankCount() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    if (const char* value = std::getenv(variable)) {
      const int size = std::atoi(value);
      if (size >= 1) return size;
    }
  }
  return 1;
}

CampaignRanks::CampaignRanks() {
  const int launched = launcherRankCount();
#ifdef PMDPLAN_WITH_MPI
  if (launched > 1 || std::getenv("OMPI_COMM_WORLD_RANK") || std::getenv("PMI_RANK")) {
    MPI_Init(nullptr, nullptr);
    initialisedMpi_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    counter_ = std::make_unique<SharedCounter>();
    const MPI_Aint bytes = rank_ == 0 ? static_cast<MPI_Aint>(sizeof(long long)) : 0;
    MPI_Win_allocate(bytes, sizeof(long long), MPI_INFO_NULL, MPI_COMM_WORLD, &counter_->value, &counter_->window);
    if (rank_ == 0) {
      MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, counter_->window);
      *counter_->value = 0;
      MPI_Win_unlock(0, counter_->window);
    }
    MPI_Barrier(MPI_COMM_WORLD);
  }
#else
  if (launched > 1)
    throw InputError("", "mpirun",
                     "this pmdplan was built without MPI, so " + std::to_string(launched) +
                         " ranks would each run the whole campaign; run it as one process, or rebuild with "
                         "libopenmpi-dev installed (CMake option PMDPLAN_WITH_MPI=ON)");
#endif
}

CampaignRanks::~CampaignRanks() {
#ifdef PMDPLAN_WITH_MPI
  if (counter_) MPI_Win_free(&counter_->window);
  if (initialisedMpi_) MPI_Finalize();
#endif
}

std::size_t CampaignRanks::takeJob() {
#ifdef PMDPLAN_WITH_MPI
  if (counter_) {
    const long long one = 1;
    long long taken = 0;
    MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, counter_->window);
    MPI_Fetch_and_op(&one, &taken, MPI_LONG_LONG, 0, 0, MPI_SUM, counter_->window);
    MPI_Win_unlock(0, counter_->window);
    return static_cast<std::size_t>(taken);
  }
#endif
  return nextJob_++;
}

std::vector<std::string> CampaignRanks::gatherToFirst(const std::string& mine) const {
  if (size_ == 1) return {mine};
#ifdef PMDPLAN_WITH_MPI
  const int length = static_cast<int>(mine.size());
  std::vector<int> lengths(rank_ == 0 ? static_cast<std::size_t>(size_) : 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> offsets(lengths.size(), 0);
  if (rank_ == 0) std::exclusive_scan(lengths.begin(), lengths.end(), offsets.begin(), 0);
  std::string all(rank_ == 0 ? static_cast<std::size_t>(offsets.back() + lengths.back()) : 0, '\0');
  MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  if (rank_ != 0) return {};
  std::vector<std::string> parts;
  for (std::size_t r = 0; r < lengths.size(); ++r)
    parts.push_back(all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r])));
  return parts;
#else
  throw std::logic_error("gatherToFirst: several ranks without MPI");
#endif
}

}  // namespace pmdplan
