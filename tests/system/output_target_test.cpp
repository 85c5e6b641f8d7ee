// resolve_output_target: what an output path leads to, and PendingFile
// writing through a FIFO or a character device.

#include "capsim/system/output_target.h"
#include "capsim/system/pending_file.h"
#include "support/cli_run.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cstring>
#include <future>
#include <stdexcept>

using namespace capsim::testing;
using capsim::OutputTarget;
using capsim::resolve_output_target;
namespace fs = std::filesystem;

namespace {

std::string refusal(const std::string& target) {
  try {
    resolve_output_target(target);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(OutputTarget, ARegularOrNewFileIsReplacedWhereItIs) {
  TempDir dir;
  std::ofstream(dir / "plain") << "x";
  for (const char* name : {"plain", "new"}) {
    const OutputTarget t = resolve_output_target(dir / name);
    EXPECT_EQ(t.kind, OutputTarget::Kind::Replace);
    EXPECT_EQ(t.path, dir / name);
  }
}

TEST(OutputTarget, LinksLeadToTheFileTheyName) {
  TempDir dir;
  fs::create_directory(dir.path() / "sub");
  std::ofstream(dir / "sub/real") << "x";
  fs::create_symlink("sub/real", dir / "one");
  fs::create_symlink("one", dir / "two");
  fs::create_symlink("sub/absent", dir / "dangling");
  fs::create_symlink("dangling", dir / "to-dangling");
  const fs::path real = fs::canonical(dir / "sub/real");
  EXPECT_EQ(resolve_output_target(dir / "one").path, real);
  EXPECT_EQ(resolve_output_target(dir / "two").path, real);
  EXPECT_EQ(resolve_output_target(dir / "dangling").path, (dir.path() / "sub/absent").string());
  EXPECT_EQ(resolve_output_target(dir / "to-dangling").path, (dir.path() / "sub/absent").string());
  EXPECT_EQ(capsim::follow_links(dir / "to-dangling"), (dir.path() / "sub/absent").string());
  EXPECT_EQ(capsim::follow_links(dir / "sub/real"), dir / "sub/real");
}

TEST(OutputTarget, FifosDevicesAndDashAreWrittenThrough) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0666), 0) << std::strerror(errno);
  fs::create_symlink("/dev/null", dir / "null");
  for (const std::string& path : {dir / "fifo", dir / "null", std::string("-")}) {
    const OutputTarget t = resolve_output_target(path);
    EXPECT_EQ(t.kind, OutputTarget::Kind::WriteThrough) << path;
    EXPECT_EQ(t.path, path);
  }
  EXPECT_TRUE(capsim::names_standard_output("-"));
  EXPECT_FALSE(capsim::names_standard_output(dir / "fifo"));
  EXPECT_FALSE(capsim::names_standard_output(dir / "null"));  // a character device is never counted
}

TEST(OutputTarget, WhatCannotTakeAFileIsRefusedWithTheReason) {
  TempDir dir;
  fs::create_directory(dir.path() / "sub");
  fs::create_symlink("loop", dir / "loop");
  EXPECT_EQ(refusal(dir / "sub"), dir / "sub: is a directory");
  EXPECT_EQ(refusal(dir / "loop"), dir / "loop: Too many levels of symbolic links");
  // A block device needs CAP_MKNOD to make; where that is missing, the rest stands.
  if (::mknod((dir / "block").c_str(), S_IFBLK | 0600, makedev(7, 200)) == 0) {
    EXPECT_EQ(refusal(dir / "block"), dir / "block: is a block device");
  }
}

// The content waits in the temporary directory, and reaches the FIFO only at commit.
TEST(PendingFileThrough, CommitCopiesTheContentIntoAFifo) {
  TempDir dir;
  const std::string fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0666), 0) << std::strerror(errno);
  capsim::PendingFile out(fifo);
  EXPECT_TRUE(out.writes_through());
  EXPECT_EQ(fs::path(out.temp_path()).parent_path(), fs::temp_directory_path());
  std::ofstream(out.temp_path()) << "content";
  const std::string temp = out.temp_path();
  std::future<std::string> read = std::async(std::launch::async, [&] { return read_file(fifo); });
  out.commit();
  EXPECT_EQ(read.get(), "content");
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), {}), 1);
}

TEST(PendingFileThrough, UncommittedNothingReachesTheTargetAndTheTemporaryFileGoes) {
  TempDir dir;
  fs::create_symlink("/dev/null", dir / "null");
  std::string temp;
  {
    capsim::PendingFile out(dir / "null");
    temp = out.temp_path();
    EXPECT_TRUE(fs::exists(temp));
  }
  EXPECT_FALSE(fs::exists(temp));
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

}  // namespace
