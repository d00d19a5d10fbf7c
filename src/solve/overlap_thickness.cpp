#include "solve/overlap_thickness.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <queue>
#include <vector>

#include "geometry/coordinate_resolution.h"
#include "solve/max_min_affine.h"

namespace pd {

namespace {

using Clock = std::chrono::steady_clock;

// The two parts' plane models of a box. They hold for every point of that box
// in the solid, so also over each box inside it: a cell's children try their
// parent's models (a small LP each) before building their own.
struct Models {
  LocalPlanes a, b;
};

struct Cell {
  Vec3 lo, hi;
  double upper;  ///< bound of φ over the cell
  int depth;
  std::shared_ptr<const Models> models;  ///< this cell's, else its nearest ancestor's; may be null
  /// What settled a box (Search::enough) when `upper` was computed: its models
  /// looked at the faces within a margin of twice that.
  double level = 0.0;
  /// The upper distance bounds at its centre, when it was probed.
  bool probed = false;
  double centre_a = INFINITY, centre_b = INFINITY;
};

struct ByUpper {
  bool operator()(const Cell& x, const Cell& y) const { return x.upper < y.upper; }
};

struct Probe {
  DistanceBounds a, b;
  double lower() const { return std::min(a.lower, b.lower); }
  double upper() const { return std::min(a.upper, b.upper); }
};

// The plane constraints one part's model puts on φ over the cell: every
// supporting plane (sd ≤ s_k + slack), and with hole planes one alternative per
// hole plane that can be the largest somewhere in the cell (sd ≤ kappa ·
// (max_k s_k + slack), so φ ≤ kappa · (s_k + slack) for some k). No
// alternative at all: no point of the cell is in the solid.
// Every alternative is the supporting planes and one plane of each hole and
// wedge, so they are kept flat: `per` functions each, one after another.
struct Alternatives {
  std::vector<Affine> base;   ///< the supporting planes: every alternative's
  std::vector<Affine> extra;  ///< alternative k's own: [k·per, (k + 1)·per)
  size_t per = 0, count = 1;
  void append(size_t k, std::vector<Affine>& f) const {
    f.insert(f.end(), base.begin(), base.end());
    const auto first = extra.begin() + static_cast<std::ptrdiff_t>(k * per);
    f.insert(f.end(), first, first + static_cast<std::ptrdiff_t>(per));
  }
};

Alternatives alternatives(const LocalPlanes& m, const Vec3& lo, const Vec3& hi) {
  Alternatives out;
  for (const FacePlane& q : m.supporting) out.base.push_back({q.offset + m.slack, -q.normal});
  const Vec3 c = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  // sd ≤ kappa · (s_q + slack) for the plane q that is the largest; one that
  // is negative throughout the cell is never the largest > 0.
  const auto can_lead = [&](const FacePlane& q, double slack) {
    return q.at(c) + half.dot(q.normal.cwiseAbs()) + slack >= 0;
  };
  // Each hole and each wedge holds on its own: every alternative so far meets
  // one of the planes that can lead.
  std::vector<Affine> next, leading;
  const auto meet = [&]() {
    next.clear();
    for (size_t k = 0; k < out.count; ++k)
      for (const Affine& g : leading) {
        const auto first = out.extra.begin() + static_cast<std::ptrdiff_t>(k * out.per);
        next.insert(next.end(), first, first + static_cast<std::ptrdiff_t>(out.per));
        next.push_back(g);
      }
    out.extra.swap(next);
    out.count *= leading.size();
    ++out.per;
  };
  const auto bound = [](const FacePlane& q, double kappa, double slack) {
    return Affine{kappa * (q.offset + slack), -kappa * q.normal};
  };
  for (const LocalPlanes::Hole& h : m.holes) {
    leading.clear();
    for (const FacePlane& q : h.planes)
      if (can_lead(q, h.slack)) leading.push_back(bound(q, h.kappa, h.slack));
    meet();
    if (out.count > static_cast<size_t>(tol::kLocalPlanesMaxChoices)) return out;
  }
  for (const LocalPlanes::Wedge& w : m.wedges) {
    leading.clear();
    for (const FacePlane* q : {&w.p, &w.q})
      if (can_lead(*q, w.slack)) leading.push_back(bound(*q, w.kappa, w.slack));
    meet();
  }
  return out;
}

class Search {
 public:
  Search(const SolidDistance& a, const SolidDistance& b, double threshold, const RigidFrame& frame)
      : frame_(frame),
        a_(a),
        b_(b),
        min_step_(std::max({1e-4 * threshold, 4 * a.noise(), 4 * b.noise()})),
        settled_(0.5 * threshold) {}

  // φ's bounds at frame point x (their nearest points in the frame too).
  Probe probe(const Vec3& x) {
    evaluations += 2;
    const Vec3 w = frame_.world(x);
    Probe p{a_.at(w), b_.at(w)};
    p.a.nearest = frame_.local(p.a.nearest);
    p.b.nearest = frame_.local(p.b.nearest);
    if (p.lower() > best) {
      best = p.lower();
      at = x;
      near_a = p.a.nearest;
    }
    return p;
  }

  // An upper bound of φ over the cell with centre probe p; -inf when the cell
  // holds no point of both solids. With `planes`, the inherited models are
  // tried first, then the cell's own, which replace them in `cell.models`
  // when built.
  double bound(Cell& cell, const Probe& p, bool planes) const {
    const double r = 0.5 * (cell.hi - cell.lo).norm();
    if (p.a.upper < -r || p.b.upper < -r) return -INFINITY;  // wholly outside a part
    double upper = p.upper() + r;                            // φ is 1-Lipschitz
    if (!planes || !(upper > best)) return upper;
    std::vector<Affine> common;
    if (std::isfinite(p.a.upper)) common.push_back({p.a.upper + r, Vec3::Zero()});
    if (std::isfinite(p.b.upper)) common.push_back({p.b.upper + r, Vec3::Zero()});
    const double enough = this->enough();
    if (cell.models) {
      upper = planes_bound(cell.models->a, cell.models->b, common, cell, upper);
      if (upper <= enough) return upper;
    }
    // Each part's model looks at the faces within a margin of the box: it
    // bounds min(sd, margin), which settles the box when the bound comes
    // below `enough`, the only use a box has for it. One part's model often
    // settles the box alone (below the best point found, or below half the
    // threshold, where it is never split): the other's is then not built.
    const FramedBox box{frame_, cell.lo, cell.hi};
    const double margin = tol::kThicknessModelMargin * enough;
    auto own = std::make_shared<Models>();
    own->a = a_.local_planes(box, margin, &faces_a_);
    if (!own->a.empty()) {
      upper = planes_bound(own->a, LocalPlanes{}, common, cell, upper);
      if (upper <= enough) return upper;
    }
    own->b = b_.local_planes(box, margin, &faces_b_);
    if (!own->b.empty()) upper = planes_bound(own->a, own->b, common, cell, upper);
    if (!own->a.empty() || !own->b.empty()) cell.models = std::move(own);
    return upper;
  }

  /// Below this a cell's bound needs no model of its own: it is below the
  /// best point found, or below half the threshold, where it is never split.
  double enough() const { return std::max(best, settled_); }
  /// Once the bracket is below the threshold, the search narrows it against
  /// the resolution: half of it is then what settles a box.
  void settle_at(double h) { settled_ = h; }

  // The cell's inherited models' bound alone (no probe of its centre).
  double inherited_bound(const Cell& cell) const {
    return planes_bound(cell.models->a, cell.models->b, {}, cell, INFINITY);
  }

  // The plane models' bound over the cell (docs/solver.md): the largest, over
  // each choice of the holes' and wedges' active planes, of max over the cell
  // of the smallest constraint; `upper` (a bound already known) when that is
  // no better or there are too many choices.
  double planes_bound(const LocalPlanes& la, const LocalPlanes& lb,
                      const std::vector<Affine>& common, const Cell& cell, double upper) const {
    const double original = upper;
    if (la.empty() && lb.empty()) return upper;
    // A model about a box and a margin bounds min(φ, margin): a bound at or
    // above the least margin says nothing.
    const double limit =
        std::min(la.empty() ? INFINITY : la.margin, lb.empty() ? INFINITY : lb.margin);
    upper = std::min(upper, limit);
    const auto alts_a = alternatives(la, cell.lo, cell.hi),
               alts_b = alternatives(lb, cell.lo, cell.hi);
    if (alts_a.count == 0 || alts_b.count == 0) return -INFINITY;  // outside a part throughout
    if (alts_a.count * alts_b.count > static_cast<size_t>(tol::kLocalPlanesMaxChoices))
      return original;
    double model = -INFINITY;
    std::vector<Affine> f;
    for (size_t x = 0; x < alts_a.count; ++x)
      for (size_t y = 0; y < alts_b.count; ++y) {
        f = common;
        alts_a.append(x, f);
        alts_b.append(y, f);
        // A choice whose cheap bound is no higher than the largest so far
        // cannot raise it: its small LP is not solved.
        if (min_max_affine(f, cell.lo, cell.hi) <= model) continue;
        model = std::max(model, max_min_affine(f, cell.lo, cell.hi));
        if (!(model < upper)) return original;
      }
    return model;
  }

  // Pattern ascent of φ from x (its probe p): steps away from the nearer
  // surface, the other, or both, halving the step when none improves.
  void ascend(Vec3 x, Probe p, double step, long budget) {
    const long stop = evaluations + budget;
    while (step > min_step_ && evaluations < stop) {
      const Vec3 ga = away(x, p.a), gb = away(x, p.b);
      bool moved = false;
      for (const Vec3& u : {ga, gb, Vec3((ga + gb).normalized())}) {
        if (!u.allFinite()) continue;
        const Vec3 y = x + step * u;
        const Probe q = probe(y);
        if (q.lower() > p.lower()) {
          x = y, p = q, moved = true;
          break;
        }
      }
      if (!moved) step *= 0.5;
    }
  }

  long evaluations = 0;
  double best = -INFINITY;
  Vec3 at = Vec3::Zero(), near_a = Vec3::Zero();

 private:
  // The direction in which sd grows at x: away from the nearest surface point
  // inside, towards it outside.
  static Vec3 away(const Vec3& x, const DistanceBounds& d) {
    const Vec3 v = (x - d.nearest).normalized();
    return d.lower > 0 ? v : Vec3(-v);
  }

  RigidFrame frame_;
  const SolidDistance &a_, &b_;
  double min_step_;
  double settled_;  ///< a box whose φ bound is below this never decides the pair
  // Each part's faces taken into the frame, kept across the boxes' models
  // (nested boxes see mostly the same faces); the models are the same without.
  mutable FrameFaces faces_a_, faces_b_;
};

// Halves every axis at least half as long as the longest (2, 4 or 8 children),
// so cells stay about cubic and a flat region is not cut across its thickness.
std::vector<Cell> split(const Cell& c) {
  const Vec3 e = c.hi - c.lo, mid = 0.5 * (c.lo + c.hi);
  std::vector<Cell> out{{c.lo, c.hi, c.upper, c.depth + 1, c.models}};
  for (int d = 0; d < 3; ++d) {
    if (e[d] < 0.5 * e.maxCoeff()) continue;
    const size_t n = out.size();
    for (size_t k = 0; k < n; ++k) {
      Cell upper = out[k];
      out[k].hi[d] = mid[d];
      upper.lo[d] = mid[d];
      out.push_back(upper);
    }
  }
  return out;
}

}  // namespace

double thickness_resolution(const SolidDistance& a, const SolidDistance& b) {
  const auto step = [](const SolidDistance& s) {
    const Eigen::AlignedBox3d& box = s.box();
    return coordinate_step(
        std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff()), true);
  };
  return tol::kContactSteps * (step(a) + step(b));
}

ThicknessResult overlap_thickness(const SolidDistance& a, const SolidDistance& b, double threshold,
                                  double upper_hint, const ThicknessLimits& limits) {
  using Outcome = ThicknessResult::Outcome;
  ThicknessResult res;
  res.resolution = limits.resolution.value_or(thickness_resolution(a, b));
  const double cap = 0.5 * upper_hint;  // on h
  // An interference's overlap is above the threshold and the resolution alike.
  const double bar = std::max(threshold, res.resolution);
  if (!a.closed() || !b.closed()) {
    res.outcome = Outcome::kNoInside;
    res.upper = upper_hint;
    return res;
  }
  const double pad = 4 * std::max(a.noise(), b.noise());
  Eigen::AlignedBox3d region = a.box().intersection(b.box());
  if (region.isEmpty()) {
    res.outcome = Outcome::kBelow;
    return res;
  }
  // The boxes of the search live in a frame of the pair's own: x = origin + R·y.
  // R is the smaller part's face axes (geometry/face_axes.h), so a seated face
  // or a pin's facets run along the boxes' sides, and the origin is the middle
  // of where the parts' boxes meet, so coordinates stay small. The search
  // region is where the smaller part's box (its vertices there) meets the
  // other's box (its corners there).
  RigidFrame frame;
  frame.origin = region.center();
  const SolidDistance& small = a.box().diagonal().norm() <= b.box().diagonal().norm() ? a : b;
  frame.R = small.axes();
  {
    // Its corners' box in the frame is the part's own (Rᵀv) less Rᵀ·origin,
    // widened by the rounding of taking them apart.
    const Vec3 shift = frame.R.transpose() * frame.origin;
    const double rounding =
        16 * std::numeric_limits<double>::epsilon() *
        (small.box_in_axes().max().cwiseAbs().maxCoeff() +
         small.box_in_axes().min().cwiseAbs().maxCoeff() + shift.cwiseAbs().maxCoeff());
    Eigen::AlignedBox3d own(small.box_in_axes().min() - shift, small.box_in_axes().max() - shift),
        meet;
    own.min().array() -= rounding;
    own.max().array() += rounding;
    for (int k = 0; k < 8; ++k)
      meet.extend(frame.local(region.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k))));
    region = own.intersection(meet);
    if (region.isEmpty()) {
      res.outcome = Outcome::kBelow;
      return res;
    }
    region.min().array() -= pad;
    region.max().array() += pad;
  }
  const auto deadline = Clock::now() + std::chrono::duration<double>(limits.seconds);
  Search s(a, b, threshold, frame);
  std::priority_queue<Cell, std::vector<Cell>, ByUpper> open;
  {
    Cell root{region.min(), region.max(), cap, 0, nullptr};
    const Probe p = s.probe(0.5 * (root.lo + root.hi));
    root.upper = std::min(cap, s.bound(root, p, false));
    if (root.upper > s.best) open.push(root);
    ++res.cells;
  }
  double last_ascent = -INFINITY;
  long decided_at = -1;  // evaluations when the interference was certified
  for (;;) {
    const double top = open.empty() ? s.best : std::max(s.best, open.top().upper);
    const double lower = 2 * std::max(0.0, s.best), upper = 2 * std::max(0.0, std::min(top, cap));
    res.lower = lower;
    res.upper = std::max(lower, upper);
    // Thin: touching to the coordinates' resolution, or an overlap found above
    // it and within the threshold. Below the threshold with neither, the
    // bracket narrows on against the resolution, so that a contact reads the
    // same at every tolerance.
    if (upper <= res.resolution || (upper <= threshold && lower > res.resolution)) {
      res.outcome = Outcome::kBelow;
      break;
    }
    if (upper <= threshold) s.settle_at(0.5 * res.resolution);
    if (lower > bar && decided_at < 0) decided_at = s.evaluations;
    // Decided thick: the bracket is tightened for the report, with at most as
    // much work again as deciding took (a union's lower bound may never come
    // within the ratio: its shared faces hide the distance from inside).
    const bool tightened =
        decided_at >= 0 &&
        (upper <= lower * (1 + tol::kThicknessBracket) || open.empty() ||
         s.evaluations - decided_at >= std::max(decided_at, tol::kThicknessBracketMinEvaluations));
    if (tightened) {
      res.outcome = Outcome::kAbove;
      break;
    }
    // Cells count too: a child settled by its parent's models costs no evaluation.
    const bool out_of_work = s.evaluations >= limits.max_evaluations ||
                             res.cells >= limits.max_evaluations || open.empty();
    const bool out_of_time = res.cells % 64 == 0 && Clock::now() > deadline;
    if (out_of_work || out_of_time) {
      res.outcome = upper <= threshold ? Outcome::kBelow  // thin, not narrowed to the end
                    : lower > bar      ? Outcome::kAbove
                    : out_of_time      ? Outcome::kTime
                                       : Outcome::kBudget;
      break;
    }
    const Cell cell = open.top();
    open.pop();
    if (!(cell.upper > s.best)) continue;
    // A box bounded while far less settled a box (before the overlap was
    // found, its models' margin a fraction of today's) is bounded again with
    // models of today's margin before it is split: one model instead of up to
    // eight probes and models.
    if (cell.depth >= 2 && cell.level < 0.5 * s.enough() && cell.probed) {
      Cell again = cell;
      again.level = s.enough();
      Probe p;
      p.a.upper = cell.centre_a;
      p.b.upper = cell.centre_b;
      again.upper = std::min(cell.upper, s.bound(again, p, true));
      if (again.upper < cell.upper) {
        if (again.upper > s.best) open.push(again);
        continue;
      }
    }
    double step = 0.0;
    for (const Cell& child : split(cell)) {
      step = 0.5 * (child.hi - child.lo).norm();
      ++res.cells;
      Cell next = child;
      // The parent's models hold over the child: where they settle it, its
      // centre is not probed (two distance queries saved, the common case).
      next.level = s.enough();
      next.probed = false;
      if (child.depth >= 2 && cell.models) {
        next.upper = std::min(cell.upper, s.inherited_bound(next));
        if (next.upper <= s.enough()) {
          if (next.upper > s.best) open.push(next);
          continue;
        }
      }
      const Probe p = s.probe(0.5 * (child.lo + child.hi));
      next.probed = true;
      next.centre_a = p.a.upper;
      next.centre_b = p.b.upper;
      next.upper = std::min(cell.upper, s.bound(next, p, child.depth >= 2));
      if (next.upper > s.best) open.push(next);
    }
    if (s.best > last_ascent && s.best > 0) {  // a new best centre: climb from it
      s.ascend(s.at, s.probe(s.at), step, 200);
      last_ascent = s.best;
    }
  }
  res.evaluations = s.evaluations;
  if (s.best > 0) {
    res.at = frame.world(s.at);
    const Vec3 d = frame.R * (s.near_a - s.at).normalized();
    if (d.allFinite()) res.direction = d;
  }
  return res;
}

}  // namespace pd
