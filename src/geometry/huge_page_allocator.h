// Memory for a part's large per-face arrays (its distance structure's faces,
// boxes and tree, and what building them needs for a moment): each block of
// at least kOwnBlockBytes is mapped on its own, at a 2 MiB boundary, and the
// kernel is asked to back it with transparent huge pages (madvise); the whole
// 2 MiB stretches of a block get them.
//
// Why: building a bearing ring's distances (201,216 faces) writes about 100 MB,
// and the first touch of each fresh 4 KiB page is a page fault: measured, two
// fifths of the build's time on a virtual machine, where a fault costs the
// most (about 3 µs). A huge page faults once per 2 MiB. Where the system
// offers none (transparent_hugepage `never`) the advice is ignored: ordinary
// memory.
//
// Fresh memory is also zeroed by the kernel, whatever its pages: a freed
// block is therefore kept (up to kKeptBytes, 128 MB, in all) and handed to the next
// request it fits, already touched: most blocks of a build are scratch that
// the next part's build asks for again, and the blocks of distances the
// refinement's budget lets go serve the next part's (the heap would give
// them back to the system, to be faulted in again). They stay kept for the
// process's life (a bounded cost, counted in docs/performance.md);
// release_kept() gives them back.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <vector>

namespace pd {

/// Blocks below this come from the ordinary heap: a part of a few thousand
/// faces, whose arrays a mapping of their own would only scatter (each
/// mapping is one of the process's limited areas, vm.max_map_count).
inline constexpr std::size_t kOwnBlockBytes = std::size_t(256) << 10;

namespace huge_pages {

inline constexpr std::size_t kHugePage = std::size_t(2) << 20;
inline constexpr std::size_t kPage = 4096;
/// The most bytes of freed blocks kept for reuse.
inline constexpr std::size_t kKeptBytes = std::size_t(128) << 20;

/// A block's length as mapped: whole small pages (the tail past the last
/// whole huge page keeps small ones, so no memory is taken beyond the block).
inline std::size_t mapped_length(std::size_t bytes) {
  return (bytes + kPage - 1) / kPage * kPage;
}

/// A block of at least `bytes`, starting at a 2 MiB boundary: a kept one it
/// fits, else freshly mapped. Throws std::bad_alloc.
void* take(std::size_t bytes);
/// Back to the kept blocks (the least recently given unmapped past kKeptBytes).
void give(void* block) noexcept;
/// Unmaps every kept block.
void release_kept() noexcept;
/// Bytes of the blocks kept now.
std::size_t kept_bytes() noexcept;

}  // namespace huge_pages

template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_alloc();
    if (n * sizeof(T) < kOwnBlockBytes) return std::allocator<T>().allocate(n);
    return static_cast<T*>(huge_pages::take(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kOwnBlockBytes)
      std::allocator<T>().deallocate(p, n);
    else
      huge_pages::give(p);
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
