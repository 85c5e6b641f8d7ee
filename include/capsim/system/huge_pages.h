#pragma once
// Memory for a run's large arrays on the kernel's transparent huge pages.
//
// Memory costs a page fault the first time each page of it is touched. With
// 4 KiB pages a large array takes a fault per 4 KiB, and in a virtual machine
// a fault can cost 10 us (docs/performance.md): the 48-byte tokens of a 300 KB
// scene file alone took some 1,500. Advised with madvise(MADV_HUGEPAGE),
// Linux backs the memory with huge pages (2 MiB on x86-64 and arm64) when its
// transparent huge pages are "madvise" or "always": one fault for 512. Embree
// places its large arrays the same way.
//
// Where the kernel has no transparent huge pages, or they are "never", the
// advice is refused and the blocks are ordinary pages; nothing else changes.

#include <cstddef>
#include <memory_resource>
#include <new>
#include <vector>

namespace capsim {

// The size of a huge page the kernel offers (its hpage_pmd_size), 2 MiB where
// it does not say.
std::size_t huge_page_bytes();

// A block of at least half a huge page is a mapping of its own, aligned to the
// huge page size, its length rounded up to a whole number of huge pages, and
// advised; a smaller one comes from std::pmr::new_delete_resource(). Thread-safe;
// it lives as long as the process. Throws std::bad_alloc when the memory
// cannot be had.
std::pmr::memory_resource* huge_page_resource();

// The allocator of a std::vector that can grow to megabytes, such as a large
// scene's primitives: its blocks come from huge_page_resource(). It holds no
// state, so such vectors move and swap as plain ones do.
template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(huge_page_resource()->allocate(n * sizeof(T), alignof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { huge_page_resource()->deallocate(p, n * sizeof(T), alignof(T)); }

  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) { return true; }
};

template <class T>
using LargeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace capsim
