#include "report/finding_groups.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "geometry/union_find.h"
#include "hash.h"
#include "results/fingerprint.h"
#include "tolerances.h"

namespace pd {

namespace {

// How far a member is from being clear: its depth, or for a clearance
// violation the clearance it lacks (its depth and the clearance when it
// overlaps).
double shortfall(const PairResult& r) {
  if (r.status == Status::kClearanceViolation && r.clearance_min && r.distance)
    return std::max(0.0, *r.clearance_min - std::max(0.0, *r.distance - r.gap_band.value_or(0.0)));
  if (r.status == Status::kClearanceViolation && r.clearance_min) return r.depth + *r.clearance_min;
  return r.depth;
}

// Deeper first: depth, then shortfall (a clearance violation apart has depth 0).
bool deeper(const PairResult& x, const PairResult& y) {
  if (x.depth != y.depth) return x.depth > y.depth;
  return shortfall(x) > shortfall(y);
}

SuggestedMove suggest_move(const std::vector<PairResult>& pairs, const FindingGroup& g,
                           const std::vector<std::string>& ids) {
  // The part in the most members (ties: the bytewise smaller id).
  std::map<int, size_t> count;
  for (size_t k : g.members) ++count[pairs[k].a], ++count[pairs[k].b];
  int part = -1;
  for (const auto& [p, n] : count)
    if (part < 0 || n > count[part] || (n == count[part] && ids[p] < ids[part])) part = p;
  // Its members whose moves of it agree with the deepest of them.
  std::vector<size_t> with;
  for (size_t k : g.members)
    if (pairs[k].a == part || pairs[k].b == part) with.push_back(k);
  const size_t anchor = *std::min_element(with.begin(), with.end(), [&](size_t x, size_t y) {
    return deeper(pairs[x], pairs[y]) || (!deeper(pairs[y], pairs[x]) && x < y);
  });
  const Vec3 m0 = move_of(pairs[anchor], part);
  SuggestedMove move;
  move.part = part;
  Vec3 sum = Vec3::Zero();
  for (size_t k : with)
    if (move_of(pairs[k], part).dot(m0) >= std::cos(tol::kGroupMoveAngle))
      move.covers.push_back(k), sum += move_of(pairs[k], part);
  move.direction = sum.norm() > 0 ? Vec3(sum.normalized()) : m0;
  for (size_t k : move.covers)
    move.length =
        std::max(move.length,
                 shortfall(pairs[k]) / std::max(1e-3, move.direction.dot(move_of(pairs[k], part))));
  return move;
}

}  // namespace

bool needs_fix(Status s) {
  return s == Status::kInterference || s == Status::kClearanceViolation;
}

Vec3 move_of(const PairResult& r, int part) {
  return part == r.b ? Vec3(r.direction) : Vec3(-r.direction);
}

FindingGroups group_findings(const std::vector<PairResult>& pairs,
                             const std::vector<std::string>& ids) {
  FindingGroups out;
  out.group_of.assign(pairs.size(), -1);
  // Each part's findings that need a fix; two of them agreeing on its move join.
  std::map<int, std::vector<size_t>> at_part;
  for (size_t k = 0; k < pairs.size(); ++k)
    if (needs_fix(pairs[k].status))
      at_part[pairs[k].a].push_back(k), at_part[pairs[k].b].push_back(k);
  UnionFind uf(pairs.size());
  const double agree = std::cos(tol::kGroupMoveAngle);
  for (const auto& [part, list] : at_part)
    for (size_t i = 0; i < list.size(); ++i)
      for (size_t j = i + 1; j < list.size(); ++j)
        if (move_of(pairs[list[i]], part).dot(move_of(pairs[list[j]], part)) >= agree)
          uf.join(list[i], list[j]);
  std::map<size_t, FindingGroup> by_root;
  for (size_t k = 0; k < pairs.size(); ++k)
    if (needs_fix(pairs[k].status)) by_root[uf.find(k)].members.push_back(k);
  for (auto& [root, g] : by_root) {
    std::vector<std::string> prints;
    for (size_t k : g.members) {
      prints.push_back(pair_fingerprint(ids[pairs[k].a], ids[pairs[k].b]));
      g.parts.push_back(pairs[k].a);
      g.parts.push_back(pairs[k].b);
    }
    // The id depends on the members' fingerprints alone: not on their order,
    // the part indices, a shard or the run.
    std::sort(prints.begin(), prints.end());
    Hasher h;
    h.add("pdcheck-group-v1");
    for (const std::string& p : prints) h.add(p);
    g.id = h.hex();
    std::sort(g.parts.begin(), g.parts.end(),
              [&](int x, int y) { return ids[x] < ids[y] || (ids[x] == ids[y] && x < y); });
    g.parts.erase(std::unique(g.parts.begin(), g.parts.end()), g.parts.end());
    g.deepest = g.members[0];
    for (size_t k : g.members)
      if (deeper(pairs[k], pairs[g.deepest])) g.deepest = k;
    g.move = suggest_move(pairs, g, ids);
    out.groups.push_back(std::move(g));
  }
  std::sort(out.groups.begin(), out.groups.end(),
            [&](const FindingGroup& x, const FindingGroup& y) {
              const PairResult &p = pairs[x.deepest], &q = pairs[y.deepest];
              if (deeper(p, q) != deeper(q, p)) return deeper(p, q);
              return x.id < y.id;
            });
  for (size_t n = 0; n < out.groups.size(); ++n)
    for (size_t k : out.groups[n].members) out.group_of[k] = static_cast<int>(n);
  return out;
}

}  // namespace pd
