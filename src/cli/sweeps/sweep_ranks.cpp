#include "cli/sweeps/sweep_ranks.h"

#ifdef CAPSIM_WITH_MPI
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "capsim/system/shared_library.h"
#endif

namespace capsim::cli {

#ifdef CAPSIM_WITH_MPI

namespace {

bool launched_by_mpi() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK"); }

// The MPI library, opened the first time a launcher has started capsim, not
// at start-up (include/capsim/system/shared_library.h): it and the libraries it
// brings (Open MPI's runtime, hwloc, libevent) cost every run their loading,
// and only a sweep under mpirun calls them. It is the library of the soname
// the build read (CAPSIM_MPI_SONAME), so the functions are the ones mpi.h
// declares.
const SharedLibrary& mpi_library() {
  static const SharedLibrary library(CAPSIM_MPI_SONAME, "capsim sweep under an MPI launcher");
  return library;
}

// The functions and handles the sweep uses, found by name. Open MPI's
// predefined handles are the addresses of objects in its library
// (MPI_COMM_WORLD is &ompi_mpi_comm_world), so they are found by name too;
// other MPIs (MPICH) define them as constants. Making the table opens the
// library; it throws std::runtime_error when the library cannot be opened,
// naming it and why.
struct Mpi {
#define CAPSIM_MPI(name) decltype(&::name) name = mpi_library().function<decltype(&::name)>(#name)
  CAPSIM_MPI(MPI_Init_thread);
  CAPSIM_MPI(MPI_Finalize);
  CAPSIM_MPI(MPI_Comm_rank);
  CAPSIM_MPI(MPI_Comm_size);
  CAPSIM_MPI(MPI_Bcast);
  CAPSIM_MPI(MPI_Send);
  CAPSIM_MPI(MPI_Recv);
#undef CAPSIM_MPI
#ifdef OPEN_MPI
  MPI_Comm world = static_cast<MPI_Comm>(mpi_library().variable<void>("ompi_mpi_comm_world"));
  MPI_Datatype uint64 = static_cast<MPI_Datatype>(mpi_library().variable<void>("ompi_mpi_uint64_t"));
  MPI_Datatype chars = static_cast<MPI_Datatype>(mpi_library().variable<void>("ompi_mpi_char"));
#else
  MPI_Comm world = MPI_COMM_WORLD;
  MPI_Datatype uint64 = MPI_UINT64_T;
  MPI_Datatype chars = MPI_CHAR;
#endif
};

// The table, made once for the process.
const Mpi& mpi() {
  static const Mpi table;
  return table;
}

// MPI counts are ints: texts go in pieces of at most 1 GiB.
constexpr std::size_t kPiece = std::size_t{1} << 30;

int piece_size(std::size_t total, std::size_t at) { return static_cast<int>(std::min(kPiece, total - at)); }

}  // namespace

SweepRanks::SweepRanks() {
  if (!launched_by_mpi()) return;
  // Only the thread that runs the command calls MPI; TBB's workers never do.
  int provided = 0;
  mpi().MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  joined_ = true;
  mpi().MPI_Comm_rank(mpi().world, &rank_);
  mpi().MPI_Comm_size(mpi().world, &size_);
}

SweepRanks::~SweepRanks() {
  if (joined_) mpi().MPI_Finalize();
}

std::string SweepRanks::broadcast(const std::string& text) const {
  if (size_ == 1) return text;
  std::uint64_t length = text.size();
  mpi().MPI_Bcast(&length, 1, mpi().uint64, 0, mpi().world);
  std::string out = rank_ == 0 ? text : std::string(length, '\0');
  for (std::size_t at = 0; at < length; at += kPiece)
    mpi().MPI_Bcast(out.data() + at, piece_size(length, at), mpi().chars, 0, mpi().world);
  return out;
}

std::vector<std::string> SweepRanks::gather(const std::string& text) const {
  if (size_ == 1) return {text};
  if (rank_ != 0) {
    std::uint64_t length = text.size();
    mpi().MPI_Send(&length, 1, mpi().uint64, 0, 0, mpi().world);
    for (std::size_t at = 0; at < length; at += kPiece)
      mpi().MPI_Send(text.data() + at, piece_size(length, at), mpi().chars, 0, 0, mpi().world);
    return {};
  }
  std::vector<std::string> all = {text};
  for (int from = 1; from < size_; ++from) {
    std::uint64_t length = 0;
    mpi().MPI_Recv(&length, 1, mpi().uint64, from, 0, mpi().world, MPI_STATUS_IGNORE);
    std::string got(length, '\0');
    for (std::size_t at = 0; at < length; at += kPiece)
      mpi().MPI_Recv(got.data() + at, piece_size(length, at), mpi().chars, from, 0, mpi().world, MPI_STATUS_IGNORE);
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
