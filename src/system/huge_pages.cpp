#include "capsim/system/huge_pages.h"

#include <sys/mman.h>

#include <cstdint>
#include <fstream>
#include <new>

namespace capsim {

namespace {

std::size_t read_huge_page_bytes() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/hpage_pmd_size");
  std::size_t bytes = 0;
  // Anything but a power of two of at least a small page is not believed.
  if (in >> bytes && bytes >= 4096 && (bytes & (bytes - 1)) == 0) return bytes;
  return std::size_t{2} << 20;
}

class HugePageResource final : public std::pmr::memory_resource {
 public:
  explicit HugePageResource(std::size_t huge) : huge_(huge) {}

 private:
  bool mapped(std::size_t bytes, std::size_t alignment) const { return bytes >= huge_ / 2 && alignment <= huge_; }
  std::size_t rounded(std::size_t bytes) const { return (bytes + huge_ - 1) / huge_ * huge_; }

  void* do_allocate(std::size_t bytes, std::size_t alignment) override {
    if (!mapped(bytes, alignment)) return std::pmr::new_delete_resource()->allocate(bytes, alignment);
    const std::size_t length = rounded(bytes);
    if (length < bytes || length > SIZE_MAX - huge_) throw std::bad_alloc();
    // A mapping a huge page longer than asked holds an aligned block of
    // `length`; the ends around it go back at once.
    void* map = ::mmap(nullptr, length + huge_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (map == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(map);
    const std::uintptr_t aligned = (start + huge_ - 1) / huge_ * huge_;
    if (aligned > start) ::munmap(map, aligned - start);
    // The tail runs from the block's end, aligned + length, to the
    // mapping's, start + length + huge_.
    if (const std::size_t tail = start + huge_ - aligned; tail > 0)
      ::munmap(reinterpret_cast<void*>(aligned + length), tail);
    // Refused (EINVAL) where the kernel has no transparent huge pages: the
    // block is then ordinary pages.
    ::madvise(reinterpret_cast<void*>(aligned), length, MADV_HUGEPAGE);
    return reinterpret_cast<void*>(aligned);
  }

  void do_deallocate(void* p, std::size_t bytes, std::size_t alignment) override {
    if (!mapped(bytes, alignment)) return std::pmr::new_delete_resource()->deallocate(p, bytes, alignment);
    ::munmap(p, rounded(bytes));
  }

  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override { return this == &other; }

  std::size_t huge_;
};

}  // namespace

std::size_t huge_page_bytes() {
  static const std::size_t bytes = read_huge_page_bytes();
  return bytes;
}

std::pmr::memory_resource* huge_page_resource() {
  // Never destroyed: blocks may be given back during the destruction of statics.
  static HugePageResource* const resource = new HugePageResource(huge_page_bytes());
  return resource;
}

}  // namespace capsim
