// MPI for `tehl sweep`: the only MPI user in tehl, kept out of the library. Built with MPI
// when CMake's TEHL_WITH_MPI is on; otherwise (or when the program was not started by an MPI
// launcher) a single rank.
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
  void Barrier() const;
  // Every rank's `text`, concatenated in rank order, on rank 0; "" on the other ranks.
  std::string GatherToRoot(const std::string& text) const;

 private:
  bool active_ = false;
  int rank_ = 0, size_ = 1;
};

}  // namespace tehl::cli
