#include "capsim/system/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace {

using capsim::huge_page_bytes;
using capsim::huge_page_resource;

// The VmFlags of the mapping of /proc/self/smaps holding `p`, nullopt when no
// mapping holds it.
std::optional<std::string> vm_flags_at(const void* p) {
  const auto address = reinterpret_cast<std::uintptr_t>(p);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t start = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    // A mapping's first line starts with its range, "start-end perms ...".
    if (range >> std::hex >> start >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
      inside = start <= address && address < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line.substr(8);
    }
  }
  return std::nullopt;
}

bool kernel_has_transparent_huge_pages() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(in, modes);
  return modes.find("[madvise]") != std::string::npos || modes.find("[always]") != std::string::npos;
}

TEST(HugePages, TheSizeIsAPowerOfTwoOfAtLeastASmallPage) {
  const std::size_t bytes = huge_page_bytes();
  EXPECT_GE(bytes, 4096u);
  EXPECT_EQ(bytes & (bytes - 1), 0u);
}

// A large block is a mapping of its own, aligned, advised for huge pages, every
// byte of it usable, and gone once given back.
TEST(HugePages, ALargeBlockIsAnAdvisedMappingOfItsOwn) {
  const std::size_t huge = huge_page_bytes();
  const std::size_t bytes = huge + huge / 2 + 40;
  void* p = huge_page_resource()->allocate(bytes, alignof(std::max_align_t));
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % huge, 0u);
  std::memset(p, 0xA5, bytes);
  EXPECT_EQ(static_cast<unsigned char*>(p)[bytes - 1], 0xA5);
  const std::optional<std::string> flags = vm_flags_at(p);
  ASSERT_TRUE(flags.has_value());
  if (kernel_has_transparent_huge_pages()) {
    EXPECT_NE(flags->find(" hg"), std::string::npos) << *flags;
  }
  // The block's two huge pages are one mapping; the rest of what was mapped
  // to align it went back.
  EXPECT_TRUE(vm_flags_at(static_cast<char*>(p) + 2 * huge - 1).has_value());
  huge_page_resource()->deallocate(p, bytes, alignof(std::max_align_t));
  EXPECT_FALSE(vm_flags_at(p).has_value());
  EXPECT_FALSE(vm_flags_at(static_cast<char*>(p) + 2 * huge - 1).has_value());
}

// Below half a huge page a block comes from the heap, never advised.
TEST(HugePages, ASmallBlockComesFromTheHeap) {
  const std::size_t bytes = huge_page_bytes() / 2 - 1;
  void* p = huge_page_resource()->allocate(bytes, 16);
  std::memset(p, 1, bytes);
  const std::optional<std::string> flags = vm_flags_at(p);
  ASSERT_TRUE(flags.has_value());
  EXPECT_EQ(flags->find(" hg"), std::string::npos) << *flags;
  huge_page_resource()->deallocate(p, bytes, 16);
}

TEST(HugePages, TheResourceIsOneAndEqualToItselfOnly) {
  EXPECT_EQ(huge_page_resource(), huge_page_resource());
  EXPECT_TRUE(huge_page_resource()->is_equal(*huge_page_resource()));
  EXPECT_FALSE(huge_page_resource()->is_equal(*std::pmr::new_delete_resource()));
}

TEST(HugePages, AnImpossibleBlockThrowsBadAlloc) {
  EXPECT_THROW(static_cast<void>(huge_page_resource()->allocate(SIZE_MAX - 4096, 16)), std::bad_alloc);
}

}  // namespace
