#include "geometry/huge_page_allocator.h"

#include <pthread.h>
#include <sys/mman.h>

#include <cstdint>
#include <iterator>
#include <list>
#include <mutex>
#include <unordered_map>

namespace pd::huge_pages {

namespace {

struct Kept {
  void* block;
  std::size_t length;
};

// Every block handed out (its mapped length), and the freed ones kept, most
// recently given last; under one lock (a few hundred blocks at most, each
// worth a build's pass over a part's faces).
struct Blocks {
  std::mutex mutex;
  std::unordered_map<void*, std::size_t> live;
  std::list<Kept> kept;
  std::size_t kept_bytes = 0;
};

Blocks& blocks() {
  // Never destroyed: blocks may be freed during exit. Held across fork(), so a
  // child never inherits it locked by a thread that is not there (the
  // processes that load files and solve pairs are forked).
  static Blocks* b = [] {
    auto* made = new Blocks;
    pthread_atfork([] { blocks().mutex.lock(); }, [] { blocks().mutex.unlock(); },
                   [] { blocks().mutex.unlock(); });
    return made;
  }();
  return *b;
}

void* map_fresh(std::size_t length) {
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

}  // namespace

void* take(std::size_t bytes) {
  const std::size_t length = mapped_length(bytes);
  Blocks& b = blocks();
  {
    std::lock_guard<std::mutex> lock(b.mutex);
    // The smallest kept block it fits; one more than twice as long is cut to
    // length (the rest unmapped), so a small request does not hold a large block.
    auto best = b.kept.end();
    for (auto it = b.kept.begin(); it != b.kept.end(); ++it)
      if (it->length >= length && (best == b.kept.end() || it->length < best->length)) best = it;
    if (best != b.kept.end()) {
      Kept k = *best;
      b.kept.erase(best);
      b.kept_bytes -= k.length;
      if (k.length > 2 * length) {
        munmap(static_cast<char*>(k.block) + length, k.length - length);
        k.length = length;
      }
      b.live.emplace(k.block, k.length);
      return k.block;
    }
  }
  void* block = map_fresh(length);
  std::lock_guard<std::mutex> lock(b.mutex);
  b.live.emplace(block, length);
  return block;
}

void give(void* block) noexcept {
  Blocks& b = blocks();
  std::lock_guard<std::mutex> lock(b.mutex);
  const auto it = b.live.find(block);
  if (it == b.live.end()) return;  // not ours: cannot happen
  const std::size_t length = it->second;
  b.live.erase(it);
  if (length > kKeptBytes) {
    munmap(block, length);
    return;
  }
  b.kept.push_back({block, length});
  b.kept_bytes += length;
  while (b.kept_bytes > kKeptBytes) {
    munmap(b.kept.front().block, b.kept.front().length);
    b.kept_bytes -= b.kept.front().length;
    b.kept.pop_front();
  }
}

void release_kept() noexcept {
  Blocks& b = blocks();
  std::lock_guard<std::mutex> lock(b.mutex);
  for (const Kept& k : b.kept) munmap(k.block, k.length);
  b.kept.clear();
  b.kept_bytes = 0;
}

std::size_t kept_bytes() noexcept {
  Blocks& b = blocks();
  std::lock_guard<std::mutex> lock(b.mutex);
  return b.kept_bytes;
}

}  // namespace pd::huge_pages
