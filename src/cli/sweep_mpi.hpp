// MPI for `tehl sweep`: the only MPI user in tehl, kept out of the library. Built with MPI
// when CMake's TEHL_WITH_MPI is on; otherwise (or when the program was not started by an MPI
// launcher) a single rank.
//
// Every rank must make the same collective calls: a rank that stopped on an error while the
// others wait in one would leave them waiting forever. The sweep therefore agrees on the
// outcome of each step (Agree) before the next collective call, and ends every rank (Abort)
// on an error that it could not agree on.
#pragma once

#include <string>

namespace tehl::cli {

class SweepMpi {
 public:
  SweepMpi();   // MPI_Init_thread when started by mpirun/mpiexec
  ~SweepMpi();  // MPI_Finalize
  SweepMpi(const SweepMpi&) = delete;
  SweepMpi& operator=(const SweepMpi&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // Whether MPI lets other threads run while the main thread makes the MPI calls
  // (MPI_THREAD_FUNNELED or more); always true for a single process without MPI.
  bool threads_allowed() const { return threads_allowed_; }

  // The outcome of one step on every rank: the highest exit code given (0: every rank
  // succeeded) and the lowest rank that gave it. Collective: every rank calls it.
  struct Outcome {
    int exit_code = 0;
    int rank = 0;
  };
  Outcome Agree(int exit_code) const;
  // Ends every rank with `exit_code` (MPI_Abort; this process only without MPI).
  [[noreturn]] void Abort(int exit_code) const;
  // Every rank's `text`, concatenated in rank order, on rank 0; "" on the other ranks.
  std::string GatherToRoot(const std::string& text) const;

 private:
  bool active_ = false;
  bool threads_allowed_ = true;
  int rank_ = 0, size_ = 1;
};

}  // namespace tehl::cli
