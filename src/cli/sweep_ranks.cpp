#include "cli/sweep_ranks.h"

#ifdef CAPSIM_WITH_MPI
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#endif

namespace capsim::cli {

#ifdef CAPSIM_WITH_MPI

namespace {

bool launched_by_mpi() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK"); }

// MPI counts are ints: texts go in pieces of at most 1 GiB.
constexpr std::size_t kPiece = std::size_t{1} << 30;

int piece_size(std::size_t total, std::size_t at) { return static_cast<int>(std::min(kPiece, total - at)); }

}  // namespace

SweepRanks::SweepRanks() {
  if (!launched_by_mpi()) return;
  // Only the thread that runs the command calls MPI; TBB's workers never do.
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  joined_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

SweepRanks::~SweepRanks() {
  if (joined_) MPI_Finalize();
}

std::string SweepRanks::broadcast(const std::string& text) const {
  if (size_ == 1) return text;
  std::uint64_t length = text.size();
  MPI_Bcast(&length, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  std::string out = rank_ == 0 ? text : std::string(length, '\0');
  for (std::size_t at = 0; at < length; at += kPiece)
    MPI_Bcast(out.data() + at, piece_size(length, at), MPI_CHAR, 0, MPI_COMM_WORLD);
  return out;
}

std::vector<std::string> SweepRanks::gather(const std::string& text) const {
  if (size_ == 1) return {text};
  if (rank_ != 0) {
    std::uint64_t length = text.size();
    MPI_Send(&length, 1, MPI_UINT64_T, 0, 0, MPI_COMM_WORLD);
    for (std::size_t at = 0; at < length; at += kPiece)
      MPI_Send(text.data() + at, piece_size(length, at), MPI_CHAR, 0, 0, MPI_COMM_WORLD);
    return {};
  }
  std::vector<std::string> all = {text};
  for (int from = 1; from < size_; ++from) {
    std::uint64_t length = 0;
    MPI_Recv(&length, 1, MPI_UINT64_T, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::string got(length, '\0');
    for (std::size_t at = 0; at < length; at += kPiece)
      MPI_Recv(got.data() + at, piece_size(length, at), MPI_CHAR, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    all.push_back(std::move(got));
  }
  return all;
}

#else  // built without MPI: this process alone

SweepRanks::SweepRanks() = default;
SweepRanks::~SweepRanks() = default;

std::string SweepRanks::broadcast(const std::string& text) const { return text; }

std::vector<std::string> SweepRanks::gather(const std::string& text) const { return {text}; }

#endif

}  // namespace capsim::cli
