#include "capsim/system/process_heap.h"
#include "capsim/system/sanitizers.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace {

// Larger than any block the test program frees before a test, so that it is
// carved from the heap's top, memory the process has never touched.
constexpr std::size_t kBlock = std::size_t{16} << 20;  // 4,096 small pages

long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// Sets the heap up with `populated` bytes, then writes every byte of a new
// block of kBlock and exits with the faults that took on stderr. Run as a
// death test in the threadsafe style, which starts the test program afresh:
// the heap is then a new process's.
[[noreturn]] void fault_a_block(std::size_t populated) {
  capsim::set_up_process_heap(populated);
  const long before = minor_faults();
  auto* block = static_cast<unsigned char*>(std::malloc(kBlock));
  if (block == nullptr) std::_Exit(2);
  std::memset(block, 0x5A, kBlock);
  // The block is otherwise never read: the compiler must not drop the writes.
  asm volatile("" : : "r"(block) : "memory");
  const long faults = minor_faults() - before;
  std::fprintf(stderr, "faults %ld\n", faults);
  std::_Exit(0);
}

bool kernel_populates() {
  void* page = ::mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (page == MAP_FAILED) return false;
  const bool done = ::madvise(page, 4096, MADV_POPULATE_WRITE) == 0;
  ::munmap(page, 4096);
  return done;
}

// Where the kernel backs all anonymous memory with huge pages, an unpopulated
// heap also takes one fault for many pages.
bool huge_pages_always() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(in, modes);
  return modes.find("[always]") != std::string::npos;
}

class ProcessHeap : public testing::Test {
 protected:
  void SetUp() override {
#ifdef CAPSIM_ADDRESS_SANITIZER
    GTEST_SKIP() << "AddressSanitizer replaces glibc's malloc, whose heap this sets up";
#endif
    if (!kernel_populates()) GTEST_SKIP() << "the kernel has no MADV_POPULATE_WRITE (Linux 5.14 and later)";
    GTEST_FLAG_SET(death_test_style, "threadsafe");
  }
};

TEST_F(ProcessHeap, APopulatedHeapTakesNoFaultsForTheBlocksCarvedFromIt) {
  EXPECT_EXIT(fault_a_block(kBlock + kBlock / 2), testing::ExitedWithCode(0), "faults [0-7]\n");
}

TEST_F(ProcessHeap, AnUnpopulatedHeapFaultsPageByPage) {
  if (huge_pages_always()) GTEST_SKIP() << "transparent huge pages are \"always\" here";
  EXPECT_EXIT(fault_a_block(0), testing::ExitedWithCode(0), "faults [0-9][0-9][0-9][0-9]\n");
}

}  // namespace
