#include "cli/sweep_mpi.hpp"

#include <cstdio>
#include <cstdlib>
#include <vector>

#ifdef TEHL_WITH_MPI
#include <mpi.h>
#endif

namespace tehl::cli {

#ifdef TEHL_WITH_MPI
namespace {
// Set by Open MPI, MPICH/Hydra and PMIx launchers; a plain `tehl sweep` stays MPI-free.
bool StartedByMpiLauncher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}
}  // namespace

SweepMpi::SweepMpi() {
  if (!StartedByMpiLauncher()) return;
  int provided = MPI_THREAD_SINGLE;
  // Only the main thread calls MPI; the scene threads never do.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  active_ = true;
  threads_allowed_ = provided >= MPI_THREAD_FUNNELED;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

SweepMpi::~SweepMpi() {
  if (active_) MPI_Finalize();
}

SweepMpi::Outcome SweepMpi::Agree(int exit_code) const {
  if (!active_) return {exit_code, rank_};
  // MPI_MAXLOC on (value, index) pairs: the highest value, and the lowest index among equals.
  struct {
    int value, index;
  } mine{exit_code, rank_}, all{0, 0};
  MPI_Allreduce(&mine, &all, 1, MPI_2INT, MPI_MAXLOC, MPI_COMM_WORLD);
  return {all.value, all.index};
}

void SweepMpi::Abort(int exit_code) const {
  std::fflush(nullptr);
  if (active_) MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::_Exit(exit_code);
}

std::string SweepMpi::GatherToRoot(const std::string& text) const {
  if (!active_) return text;
  int n = static_cast<int>(text.size());
  std::vector<int> counts(size_), offsets(size_);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < size_; ++r) {
    offsets[r] = total;
    total += counts[r];
  }
  std::string all(rank_ == 0 ? total : 0, '\0');
  MPI_Gatherv(text.data(), n, MPI_CHAR, all.data(), counts.data(), offsets.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  return rank_ == 0 ? all : std::string();
}
#else
SweepMpi::SweepMpi() = default;
SweepMpi::~SweepMpi() = default;
SweepMpi::Outcome SweepMpi::Agree(int exit_code) const { return {exit_code, 0}; }
void SweepMpi::Abort(int exit_code) const {
  std::fflush(nullptr);
  std::_Exit(exit_code);
}
std::string SweepMpi::GatherToRoot(const std::string& text) const { return text; }
#endif

}  // namespace tehl::cli
