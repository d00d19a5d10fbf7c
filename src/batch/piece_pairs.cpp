#include "batch/piece_pairs.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

namespace pd {

double box_gap(const Aabb& a, const Aabb& b) {
  const Vec3 gap = (a.lo - b.hi).cwiseMax(b.lo - a.hi).cwiseMax(0.0);
  return gap.norm();
}

PieceOutcome make_outcome(int i, int j, double depth, const Vec3& direction,
                          const std::optional<double>& distance) {
  PieceOutcome o;
  o.i = i;
  o.j = j;
  o.value = depth > 0 ? depth : -distance.value_or(0.0);
  o.direction = direction;
  o.distance = distance;
  return o;
}

PiecePairsResult combine_piece_outcomes(const std::vector<PieceOutcome>& outcomes) {
  if (outcomes.empty()) throw std::logic_error("combine_piece_outcomes: no piece pair");
  PiecePairsResult r;
  const PieceOutcome* best = nullptr;
  for (const PieceOutcome& o : outcomes) {
    r.stats += o.stats;
    if (!o.fallback.empty()) r.fallback = o.fallback;
    if (!best || o.value > best->value) best = &o;
  }
  r.solved = static_cast<int>(outcomes.size());
  r.value = best->value;
  r.depth = std::max(0.0, best->value);
  r.direction = best->direction;
  r.piece_a = best->i;
  r.piece_b = best->j;
  r.distance = best->distance;
  return r;
}

PiecePairsResult solve_piece_pairs(const std::vector<Aabb>& a, const std::vector<Aabb>& b,
                                   const std::function<PieceOutcome(int i, int j)>& solve) {
  std::vector<PieceOutcome> solved;
  std::vector<std::pair<double, std::pair<int, int>>> apart;  // (box gap, pieces)
  for (int i = 0; i < static_cast<int>(a.size()); ++i)
    for (int j = 0; j < static_cast<int>(b.size()); ++j) {
      if (a[i].overlaps(b[j]))
        solved.push_back(solve(i, j));
      else
        apart.push_back({box_gap(a[i], b[j]), {i, j}});
    }
  double best = -std::numeric_limits<double>::infinity();
  for (const PieceOutcome& o : solved) best = std::max(best, o.value);
  if (best <= 0) {  // nothing overlaps: the closest pair may lie among the box-disjoint ones
    std::stable_sort(apart.begin(), apart.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [gap, ij] : apart) {
      if (best >= -gap) break;  // this pair and the rest are at least `gap` apart
      solved.push_back(solve(ij.first, ij.second));
      best = std::max(best, solved.back().value);
    }
  }
  return combine_piece_outcomes(solved);
}

}  // namespace pd
