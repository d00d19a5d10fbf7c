// Pairs handed to the refinement's threads in their locality order, where a
// thread skips a little ahead past a pair whose part another thread is still
// fetching: a part's distances take up to 0.3 s to build (a bearing ring's),
// and a second thread asking for them meanwhile would only wait
// (ByteCache::get). The pairs taken stay close in the order, so a part's
// distances are still built about once. Only the order of the work changes,
// never a pair's result.
#pragma once

#include <cstddef>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace pd {

class PairQueue {
 public:
  /// `parts[k]`: the two parts of item k, in the order the items are to run;
  /// `lookahead`: how many open items past the first a thread may look at.
  PairQueue(std::vector<std::pair<int, int>> parts, size_t lookahead);

  /// The next item to run: the first open one whose parts no other thread is
  /// fetching among the first `lookahead` + 1 open items, else the first open
  /// one (its parts are then waited for); nullopt when every item is taken.
  /// Its parts count as being fetched until fetched().
  std::optional<size_t> take();
  /// Item k's parts are in hand: other threads may take their pairs freely.
  void fetched(size_t k);

 private:
  std::mutex mutex_;
  std::vector<std::pair<int, int>> parts_;
  size_t lookahead_;
  std::vector<char> taken_;
  size_t first_open_ = 0;
  std::vector<int> fetching_;  ///< per part: threads fetching it now
};

}  // namespace pd
