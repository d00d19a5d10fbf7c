#include "batch/refine_cache.h"

#include "batch/content_hashes.h"
#include "cache_file.h"
#include "hash.h"
#include "results/codec.h"
#include "tolerances.h"

namespace pd {

namespace {

// 2: the "solved" flag moved into the checked body (cache_file.h).
// 3: nonconvex pairs decided by the overlap thickness (at, reason, undecided).
// 4: wedge models at concave edges decide more pairs by the thickness.
// 5: the result as results/codec.h's complete encoding alone.
// 6: the settings keyed as the settings hash keys them (the seed as an integer,
//    not a double that merged seeds differing above 2^53).
// 7: StopReason gained epa-certificate before certificate (enum values moved).
// 8: every finding has `at` (pieces and vertex pairs had none); several holes
//    per plane model.
// 10: the surface depth follows the deepest pieces first, halving them across
//     their longest edge; a decided thick pair's bracket is tightened with a
//     bounded effort.
// 11: the thickness searches in the frame of the smaller part's flat areas
//     (the same certificates, other brackets).
// 12: the frame's box comes from the part's own (found once per part):
//     brackets move in their last digits.
// 13: a box's plane models look at the faces within a margin of the box and
//     bound min(sd, margin), a hole's feet move along the bisector of its
//     normals farthest apart when it spreads less: other boxes, other brackets.
// 14: a clearance is violated by touching pieces too; pairs carry `duplicate`.
// 15: a bracket with no overlap above the coordinates' resolution narrows
//     until it shows one or comes within it (separated); a decided depth is
//     the shortest decimal in its bracket; stale boxes are bounded again.
constexpr CacheKind kRefinementCache{"pdcheck-refinement-15", ".pdr"};

void add_points(Hasher& h, const Points& p) {
  h.add(std::string_view(reinterpret_cast<const char*>(p.data()), sizeof(double) * p.size()));
}

void add_part(Hasher& h, const Part& p, std::optional<bool> convex) {
  h.add("part").add(static_cast<double>(static_cast<int>(p.mode)));
  h.add(convex ? (*convex ? "convex" : "nonconvex") : "unmeasured");
  h.add(static_cast<double>(p.pieces.size()));
  for (const Hull& piece : p.pieces) add_points(h, piece.vertices);
  if (p.surface) {
    h.add(p.surface->file_hash);
    for (int k = 0; k < 16; ++k) h.add(p.surface->placement(k / 4, k % 4));
    h.add(p.surface->stretch);
  }
}

}  // namespace

std::string refinement_key(const Part& a, std::optional<bool> convex_a, const Part& b,
                           std::optional<bool> convex_b, const PairResult& hull,
                           const RunOptions& options, const PairChecks& checks) {
  Hasher h;
  h.add(kRefinementCache.format);
  add_part(h, a, convex_a);
  add_part(h, b, convex_b);
  h.add(status_name(hull.status)).add(hull.depth);
  for (int k = 0; k < 3; ++k) h.add(hull.direction[k]);
  h.add(options.tolerance).add(options.pair_timeout);
  add_solver_settings(h, options.solver);
  h.add(checks.clearance ? *checks.clearance : -1.0);
  h.add(checks.tolerance ? checks.tolerance->value : -1.0);
  for (double x :
       {tol::kConcavityFraction, tol::kDecomposeSeconds,
        static_cast<double>(tol::kThicknessMaxEvaluations), tol::kThicknessSeconds,
        tol::kThicknessBracket, static_cast<double>(tol::kThicknessBracketMinEvaluations),
        tol::kThicknessModelMargin, static_cast<double>(tol::kSurfaceDepthSamples),
        static_cast<double>(tol::kSurfaceDepthGuardSamples),
        static_cast<double>(tol::kLocalPlanesMaxFaces),
        static_cast<double>(tol::kLocalPlanesMaxPlanes),
        static_cast<double>(tol::kLocalPlanesMaxChoices), tol::kLocalPlanesMaxKappa,
        static_cast<double>(tol::kLocalPlanesMaxWedges),
        static_cast<double>(tol::kLocalPlanesWedgeTries), tol::kLocalPlanesFacingCos,
        static_cast<double>(tol::kDecomposeMaxWork), static_cast<double>(tol::kDecomposeSamples)})
    h.add(x);
  return h.hex();
}

// Body: the "solved" flag (0 or 1) line, then the result in the complete
// encoding (results/codec.h: every field, lossless for doubles).
std::optional<StoredRefinement> read_cached_refinement(const std::string& dir,
                                                       const std::string& key) {
  const std::optional<std::string> body = read_cache_entry(dir, kRefinementCache, key);
  if (!body || body->size() < 2 || ((*body)[0] != '0' && (*body)[0] != '1') || (*body)[1] != '\n')
    return std::nullopt;
  try {
    StoredRefinement r;
    r.result = decode_pair_result(body->substr(2));
    r.solved = (*body)[0] == '1';
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string write_cached_refinement(const std::string& dir, const std::string& key,
                                    const StoredRefinement& r) {
  return write_cache_entry(dir, kRefinementCache, key,
                           std::string(r.solved ? "1" : "0") + "\n" + encode_pair_result(r.result));
}

}  // namespace pd
