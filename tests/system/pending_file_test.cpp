// PendingFile: an output that appears whole or not at all.

#include "capsim/system/pending_file.h"
#include "support/cli_run.h"

#include <stdexcept>

using namespace capsim::testing;
using capsim::PendingFile;

namespace {

std::size_t entry_count(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

TEST(PendingFile, CreatesAHiddenTemporaryFileBesideTheTarget) {
  TempDir dir;
  const PendingFile f(dir / "out.png");
  EXPECT_EQ(f.target(), dir / "out.png");
  const std::filesystem::path temp(f.temp_path());
  EXPECT_EQ(temp.parent_path(), dir.path());
  EXPECT_EQ(temp.filename().string().rfind(".out.png.", 0), 0u) << temp;
  EXPECT_EQ(temp.extension(), ".tmp");
  EXPECT_TRUE(std::filesystem::is_regular_file(temp));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(PendingFile, CommitPutsTheContentInPlaceOfTheTarget) {
  TempDir dir;
  std::ofstream(dir / "out.txt") << "old";
  PendingFile f(dir / "out.txt");
  std::ofstream(f.temp_path()) << "new";
  EXPECT_EQ(read_file(dir / "out.txt"), "old");
  f.commit();
  EXPECT_EQ(read_file(dir / "out.txt"), "new");
  EXPECT_EQ(entry_count(dir.path()), 1u);
}

TEST(PendingFile, WithoutCommitNothingIsLeft) {
  TempDir dir;
  {
    PendingFile f(dir / "out.txt");
    std::ofstream(f.temp_path()) << "half";
  }
  EXPECT_EQ(entry_count(dir.path()), 0u);
}

TEST(PendingFile, CommitAllChangesNothingUntilEveryFileIsWritten) {
  TempDir dir;
  std::vector<PendingFile> files;
  files.emplace_back(dir / "a");
  files.emplace_back(dir / "b");
  for (const PendingFile& f : files) std::ofstream(f.temp_path()) << f.target();
  capsim::commit_all(files);
  EXPECT_EQ(read_file(dir / "a"), dir / "a");
  EXPECT_EQ(read_file(dir / "b"), dir / "b");
  EXPECT_EQ(entry_count(dir.path()), 2u);
}

// The message is exactly `message`, or, when that ends in ": ", starts with it
// and goes on with the system's reason.
void expect_refused(const std::string& target, const std::string& message) {
  try {
    PendingFile f(target);
    ADD_FAILURE() << target << " was accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (message.size() >= 2 && message.compare(message.size() - 2, 2, ": ") == 0) {
      EXPECT_EQ(what.rfind(message, 0), 0u) << what;
      EXPECT_GT(what.size(), message.size()) << what;
    } else {
      EXPECT_EQ(what, message);
    }
  }
}

TEST(PendingFile, RefusesWhatCannotBeAFileWithTheReason) {
  TempDir dir;
  std::filesystem::create_directory(dir / "sub");
  std::ofstream(dir / "plain") << "x";
  expect_refused(dir / "sub", dir / "sub: is a directory");
  expect_refused(dir / "sub/", dir / "sub/: names a directory, not a file");
  expect_refused(dir / "sub/..", dir / "sub/..: names a directory, not a file");
  expect_refused(dir / "missing/x", dir / "missing/x: directory " + (dir / "missing") + " does not exist");
  expect_refused(dir / "plain/x", dir / "plain/x: " + (dir / "plain") + " is not a directory");
  // No one may create files in /proc, root included.
  expect_refused("/proc/capsim-pending", "/proc/capsim-pending: cannot create a file in /proc: ");
  EXPECT_EQ(entry_count(dir.path()), 2u);
}

}  // namespace
