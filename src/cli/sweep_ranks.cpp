#include "cli/sweep_ranks.h"

#ifdef CAPSIM_WITH_MPI
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "capsim/shared_library.h"
#endif

namespace capsim::cli {

#ifdef CAPSIM_WITH_MPI

namespace {

bool launched_by_mpi() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK"); }

// The MPI library, opened the first time a launcher has started capsim, not
// at start-up (include/capsim/shared_library.h): it and the libraries it
// brings (Open MPI's runtime, hwloc, libevent) cost every run their loading,
// and only a sweep under mpirun calls them. capsim compiles against mpi.h and
// calls the library of the same soname (CAPSIM_MPI_SONAME, read by the
// build). Open MPI's predefined handles are the addresses of objects in its
// library (MPI_COMM_WORLD is &ompi_mpi_comm_world), so they are found by name
// too; other MPIs (MPICH) define them as constants.
struct Mpi {
  decltype(&MPI_Init_thread) init_thread;
  decltype(&MPI_Finalize) finalize;
  decltype(&MPI_Comm_rank) comm_rank;
  decltype(&MPI_Comm_size) comm_size;
  decltype(&MPI_Bcast) bcast;
  decltype(&MPI_Send) send;
  decltype(&MPI_Recv) recv;
  MPI_Comm world;
  MPI_Datatype uint64;
  MPI_Datatype chars;
};

const Mpi& mpi() {
  static const SharedLibrary library(CAPSIM_MPI_SONAME, "capsim sweep under an MPI launcher");
  static const Mpi m = [] {
    Mpi f;
    f.init_thread = library.function<decltype(f.init_thread)>("MPI_Init_thread");
    f.finalize = library.function<decltype(f.finalize)>("MPI_Finalize");
    f.comm_rank = library.function<decltype(f.comm_rank)>("MPI_Comm_rank");
    f.comm_size = library.function<decltype(f.comm_size)>("MPI_Comm_size");
    f.bcast = library.function<decltype(f.bcast)>("MPI_Bcast");
    f.send = library.function<decltype(f.send)>("MPI_Send");
    f.recv = library.function<decltype(f.recv)>("MPI_Recv");
#ifdef OPEN_MPI
    f.world = static_cast<MPI_Comm>(library.variable<void>("ompi_mpi_comm_world"));
    f.uint64 = static_cast<MPI_Datatype>(library.variable<void>("ompi_mpi_uint64_t"));
    f.chars = static_cast<MPI_Datatype>(library.variable<void>("ompi_mpi_char"));
#else
    f.world = MPI_COMM_WORLD;
    f.uint64 = MPI_UINT64_T;
    f.chars = MPI_CHAR;
#endif
    return f;
  }();
  return m;
}

// MPI counts are ints: texts go in pieces of at most 1 GiB.
constexpr std::size_t kPiece = std::size_t{1} << 30;

int piece_size(std::size_t total, std::size_t at) { return static_cast<int>(std::min(kPiece, total - at)); }

}  // namespace

SweepRanks::SweepRanks() {
  if (!launched_by_mpi()) return;
  // Only the thread that runs the command calls MPI; TBB's workers never do.
  int provided = 0;
  mpi().init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  joined_ = true;
  mpi().comm_rank(mpi().world, &rank_);
  mpi().comm_size(mpi().world, &size_);
}

SweepRanks::~SweepRanks() {
  if (joined_) mpi().finalize();
}

std::string SweepRanks::broadcast(const std::string& text) const {
  if (size_ == 1) return text;
  std::uint64_t length = text.size();
  mpi().bcast(&length, 1, mpi().uint64, 0, mpi().world);
  std::string out = rank_ == 0 ? text : std::string(length, '\0');
  for (std::size_t at = 0; at < length; at += kPiece)
    mpi().bcast(out.data() + at, piece_size(length, at), mpi().chars, 0, mpi().world);
  return out;
}

std::vector<std::string> SweepRanks::gather(const std::string& text) const {
  if (size_ == 1) return {text};
  if (rank_ != 0) {
    std::uint64_t length = text.size();
    mpi().send(&length, 1, mpi().uint64, 0, 0, mpi().world);
    for (std::size_t at = 0; at < length; at += kPiece)
      mpi().send(text.data() + at, piece_size(length, at), mpi().chars, 0, 0, mpi().world);
    return {};
  }
  std::vector<std::string> all = {text};
  for (int from = 1; from < size_; ++from) {
    std::uint64_t length = 0;
    mpi().recv(&length, 1, mpi().uint64, from, 0, mpi().world, MPI_STATUS_IGNORE);
    std::string got(length, '\0');
    for (std::size_t at = 0; at < length; at += kPiece)
      mpi().recv(got.data() + at, piece_size(length, at), mpi().chars, from, 0, mpi().world, MPI_STATUS_IGNORE);
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
