// A pair of parts as the pairs of their convex pieces: one place decides the
// pair's depth, distance and direction from its piece pairs, for the static,
// clearance and motion checks alike.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/aabb.h"
#include "solve/result.h"

namespace pd {

/// One piece pair's answer as a signed value: the depth when it overlaps (> 0),
/// −distance when apart and the distance is known, 0 when touching or apart by
/// an unknown distance (a depth method that stops at "separated" says no more).
/// make_outcome builds one from a depth and an optional distance.
struct PieceOutcome {
  int i = 0, j = 0;  ///< piece of a, piece of b
  double value = 0.0;
  Vec3 direction = Vec3::UnitZ();  ///< as DepthSolution::direction, from a to b
  std::optional<double> distance;  ///< when known (0 when touching or overlapping)
  SolveStats stats;
  std::string fallback;
};

/// The pair's answer: the largest signed value over its piece pairs (the deepest
/// overlap, else the smallest gap), with the direction and pieces that realise it.
struct PiecePairsResult {
  double depth = 0.0;              ///< max(0, value)
  double value = 0.0;              ///< the realising piece pair's signed value
  Vec3 direction = Vec3::UnitZ();  ///< the realising piece pair's direction
  std::optional<double> distance;  ///< the realising piece pair's, when known
  int piece_a = 0, piece_b = 0;    ///< the realising piece pair
  SolveStats stats;                ///< summed over every solved piece pair
  std::string fallback;            ///< the last piece pair's fallback, if any
  int solved = 0;                  ///< piece pairs solved (the others were settled by boxes)
};

PieceOutcome make_outcome(int i, int j, double depth, const Vec3& direction,
                          const std::optional<double>& distance);

/// Combines solved piece pairs (non-empty): the largest value wins, the first on
/// ties. A pair is apart by a known distance only if the closest piece pair is;
/// its direction then separates that piece pair (for nonconvex parts no single
/// plane need separate the whole pair).
PiecePairsResult combine_piece_outcomes(const std::vector<PieceOutcome>& outcomes);

/// Solves what it takes of the piece pairs (boxes `a` × `b`, non-empty) to know
/// the combined answer: every pair whose boxes overlap (others cannot overlap);
/// if none overlaps, the box-disjoint pairs in order of box gap while one could
/// still be closer than the best known (a box gap is a lower bound of the
/// distance) — at least one, so the direction always separates a solved piece pair.
PiecePairsResult solve_piece_pairs(const std::vector<Aabb>& a, const std::vector<Aabb>& b,
                                   const std::function<PieceOutcome(int i, int j)>& solve);

/// The distance between two boxes (0 when they overlap or touch).
double box_gap(const Aabb& a, const Aabb& b);

}  // namespace pd
