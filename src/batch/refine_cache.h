// Cached refinements of flagged pairs (batch/refine.h): the decided result of a
// pair — mesh test, deepest-vertex bound, piece-pair solves — stored in the
// decomposition cache's directory, so a rerun on unchanged parts and placements
// pays none of it. Entries are checked cache files (cache_file.h): one that
// does not read back whole (truncated, edited, another key or format) is
// ignored and recomputed.
#pragma once

#include <optional>
#include <string>

#include "batch/pair_solve.h"
#include "batch/run.h"
#include "results/pair_result.h"
#include "scene/parts.h"

namespace pd {

struct StoredRefinement {
  PairResult result;    ///< as decided (part indices are the caller's to set)
  bool solved = false;  ///< piece pairs were solved (its parts were decomposed)
};

/// The key of pair (a, b)'s refinement: the geometry of both parts (their hull
/// vertices; for mesh parts also the file's content hash and placement), their
/// pieces modes and convexity (`convex_a`, `convex_b`: as the pair knows them,
/// batch/convexity_on_demand.h), the hull stage's answer, the tolerance, the
/// solver method and settings, the pair's checks, the decomposition settings
/// and the format.
std::string refinement_key(const Part& a, std::optional<bool> convex_a, const Part& b,
                           std::optional<bool> convex_b, const PairResult& hull,
                           const RunOptions& options, const PairChecks& checks);
/// The same with the parts' own convexity.
inline std::string refinement_key(const Part& a, const Part& b, const PairResult& hull,
                                  const RunOptions& options, const PairChecks& checks) {
  return refinement_key(a, a.convex, b, b.convex, hull, options, checks);
}

std::optional<StoredRefinement> read_cached_refinement(const std::string& dir,
                                                       const std::string& key);

/// Stores the entry (creating `dir`); returns "" or why it could not.
std::string write_cached_refinement(const std::string& dir, const std::string& key,
                                    const StoredRefinement& r);

}  // namespace pd
