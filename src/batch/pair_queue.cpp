#include "batch/pair_queue.h"

#include <algorithm>

namespace pd {

PairQueue::PairQueue(std::vector<std::pair<int, int>> parts, size_t lookahead)
    : parts_(std::move(parts)), lookahead_(lookahead), taken_(parts_.size(), 0) {
  int most = -1;
  for (const auto& [a, b] : parts_) most = std::max({most, a, b});
  fetching_.assign(size_t(most + 1), 0);
}

std::optional<size_t> PairQueue::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  while (first_open_ < taken_.size() && taken_[first_open_]) ++first_open_;
  if (first_open_ == taken_.size()) return std::nullopt;
  size_t pick = first_open_;
  size_t seen = 0;
  for (size_t k = first_open_; k < taken_.size() && seen <= lookahead_; ++k) {
    if (taken_[k]) continue;
    ++seen;
    const auto [a, b] = parts_[k];
    if (!fetching_[size_t(a)] && !fetching_[size_t(b)]) {
      pick = k;
      break;
    }
  }
  taken_[pick] = 1;
  ++fetching_[size_t(parts_[pick].first)];
  ++fetching_[size_t(parts_[pick].second)];
  return pick;
}

void PairQueue::fetched(size_t k) {
  std::lock_guard<std::mutex> lock(mutex_);
  --fetching_[size_t(parts_[k].first)];
  --fetching_[size_t(parts_[k].second)];
}

}  // namespace pd
