#pragma once
// The processes a sweep runs on (docs/sweeps.md): this one alone, or the
// ranks of the MPI job that started it. A capsim built with MPI joins a job
// only when an MPI launcher started it, as the environment tells: Open MPI's
// mpirun sets OMPI_COMM_WORLD_SIZE, a PMIx launcher (srun) PMIX_RANK. Started
// any other way it never initialises MPI (no singleton), so it runs exactly as
// a capsim built without MPI, and the other commands never touch MPI.

#include <string>
#include <vector>

namespace capsim::cli {

class SweepRanks {
 public:
  // Joins the job when built with MPI and launched by one; otherwise this
  // process is rank 0 of 1.
  SweepRanks();
  ~SweepRanks();
  SweepRanks(const SweepRanks&) = delete;
  SweepRanks& operator=(const SweepRanks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  // Rank 0's text, returned on every rank. Every rank must call it.
  std::string broadcast(const std::string& text) const;
  // Every rank's text, on rank 0 in rank order (its own first); nothing on
  // the others. Every rank must call it.
  std::vector<std::string> gather(const std::string& text) const;

 private:
  bool joined_ = false;
  int rank_ = 0, size_ = 1;
};

}  // namespace capsim::cli
