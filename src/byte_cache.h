// A cache of shared, immutable values bounded in bytes: what a stage builds
// per part (its surface's distance structure) and reuses across that part's
// pairs, kept while the budget lasts. A value in use is never dropped, so
// what is resident is at most the budget plus what the running tasks hold
// (the largest pair per thread).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <future>
#include <list>
#include <map>
#include <memory>
#include <mutex>

namespace pd {

template <class Key, class Value>
class ByteCache {
 public:
  using Ptr = std::shared_ptr<const Value>;
  /// A value and the bytes it holds.
  struct Built {
    Ptr value;
    size_t bytes = 0;
  };

  explicit ByteCache(size_t budget) : budget_(budget) {}

  /// The value of `key`: kept, or made by `build` (outside the lock; another
  /// caller of the same key meanwhile waits for it). Then, while the kept
  /// values exceed the budget, the least recently used that no caller holds
  /// are dropped. An exception of `build` reaches every caller waiting for
  /// that key, and nothing is kept. Every call makes room so.
  Ptr get(const Key& key, const std::function<Built()>& build) {
    std::shared_ptr<std::promise<Ptr>> mine;
    std::shared_future<Ptr> value;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = entries_.find(key);
      if (it != entries_.end()) {
        ++hits_;
        order_.splice(order_.end(), order_, it->second.used);  // most recent last
        value = it->second.value;
        if (it->second.bytes > 0) {  // built: taken here, then room made for others
          Ptr p = value.get();
          drop_unused();
          return p;
        }
      } else {
        ++builds_;
        mine = std::make_shared<std::promise<Ptr>>();
        order_.push_back(key);
        value = mine->get_future().share();
        entries_.emplace(key, Entry{value, 0, std::prev(order_.end())});
      }
    }
    if (!mine) return value.get();  // rethrows what its builder threw
    Built b;
    try {
      b = build();
    } catch (...) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = entries_.find(key);
        order_.erase(it->second.used);
        entries_.erase(it);
      }
      mine->set_exception(std::current_exception());
      throw;
    }
    mine->set_value(b.value);
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.at(key).bytes = std::max<size_t>(b.bytes, 1);
    bytes_ += std::max<size_t>(b.bytes, 1);
    peak_ = std::max(peak_, bytes_);
    drop_unused();
    return b.value;
  }

  /// Drops the kept value of `key` now (its memory goes when its last holder
  /// lets it go): a value no later task will ask for. Nothing while it is
  /// being built.
  void erase(const Key& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = entries_.find(key);
    if (it == entries_.end() || it->second.bytes == 0) return;
    bytes_ -= it->second.bytes;
    order_.erase(it->second.used);
    entries_.erase(it);
  }

  size_t builds() const { return builds_; }
  /// Values dropped to keep within the budget, so far.
  size_t drops() const { return drops_; }
  size_t hits() const { return hits_; }
  /// The most bytes the kept values held at once.
  size_t peak_bytes() const { return peak_; }

 private:
  struct Entry {
    std::shared_future<Ptr> value;
    size_t bytes = 0;  ///< 0 while being built
    typename std::list<Key>::iterator used;
  };

  // Under the lock. A built value's only holder is then its future's state.
  void drop_unused() {
    for (auto it = order_.begin(); bytes_ > budget_ && it != order_.end();) {
      auto e = entries_.find(*it);
      if (e->second.bytes > 0 && e->second.value.get().use_count() == 1) {
        bytes_ -= e->second.bytes;
        ++drops_;
        entries_.erase(e);
        it = order_.erase(it);
      } else {
        ++it;
      }
    }
  }

  size_t budget_;
  std::mutex mutex_;
  std::map<Key, Entry> entries_;
  std::list<Key> order_;  ///< least recently used first
  std::atomic<size_t> drops_{0};
  size_t bytes_ = 0, peak_ = 0, builds_ = 0, hits_ = 0;
};

}  // namespace pd
