// Memory for a part's large per-face arrays (its distance structure's faces,
// boxes and tree, and what building them needs for a moment): each block of
// at least kHugeBlockBytes is mapped on its own, at a 2 MiB boundary, and the
// kernel is asked to back it with transparent huge pages (madvise).
//
// Why: building a bearing ring's distances (201,216 faces) writes about 100 MB
// of fresh memory, and the first touch of each 4 KiB page is a page fault:
// measured, two fifths of the build's time on a virtual machine (where a fault
// costs the most). A huge page faults once per 2 MiB. Where the system offers
// no huge pages (transparent_hugepage `never`), the advice is ignored and the
// block is ordinary memory. A freed block is unmapped at once: it goes back to
// the system, as the distances cache's budget expects (batch/part_solids.h).
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

namespace pd {

/// Blocks below this come from the ordinary heap: a huge page for them would
/// mostly hold nothing.
inline constexpr std::size_t kHugeBlockBytes = std::size_t(4) << 20;

namespace huge_pages {

inline constexpr std::size_t kHugePage = std::size_t(2) << 20;
inline constexpr std::size_t kPage = 4096;

/// The block's length as mapped: whole small pages (the tail past the last
/// whole huge page keeps small ones, so no memory is taken beyond the block).
inline std::size_t mapped_length(std::size_t bytes) {
  return (bytes + kPage - 1) / kPage * kPage;
}

inline void* map(std::size_t bytes) {
  const std::size_t length = mapped_length(bytes);
  // Mapped a huge page longer, then trimmed to start at a 2 MiB boundary.
  void* raw =
      mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) munmap(raw, aligned - start);
  const std::size_t tail = start + length + kHugePage - (aligned + length);
  if (tail > 0) munmap(reinterpret_cast<void*>(aligned + length), tail);
  void* block = reinterpret_cast<void*>(aligned);
#ifdef MADV_HUGEPAGE
  madvise(block, length, MADV_HUGEPAGE);  // advice: ignored where none are offered
#endif
  return block;
}

inline void unmap(void* block, std::size_t bytes) {
  munmap(block, mapped_length(bytes));
}

}  // namespace huge_pages

template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_alloc();
    if (n * sizeof(T) < kHugeBlockBytes) return std::allocator<T>().allocate(n);
    return static_cast<T*>(huge_pages::map(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugeBlockBytes)
      std::allocator<T>().deallocate(p, n);
    else
      huge_pages::unmap(p, n * sizeof(T));
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
  template <class U>
  bool operator!=(const HugePageAllocator<U>&) const noexcept {
    return false;
  }
};

/// A vector whose large blocks are backed by huge pages (HugePageAllocator).
template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace pd
