// Each part's distances (SolidDistance), built once from its surface and kept
// until its last pair is done, while the run's memory budget lasts: a part's
// convexity measure and its pairs' refinement ask for the same distances (a
// bearing ring is measured nonconvex, then refined against its balls), and
// they cost more to build than most of its pairs' searches.
#pragma once

#include <atomic>
#include <memory>
#include <vector>

#include "byte_cache.h"
#include "geometry/solid_distance.h"
#include "scene/parts.h"

namespace pd {

/// What a part's distances hold, for the cache's budget (tol::kSolidBytesPerTriangle).
size_t solid_bytes(long triangles);

/// The surface a part's distances are of: its own placed (a surface kept at
/// an identity placement: the file's mesh itself, to the bit and not copied),
/// else (inline or convex parts without one kept) the triangulated hull of
/// each of its pieces.
std::shared_ptr<const Mesh> surface_mesh(const Part& p);

/// The part's placed surface is its file's mesh unchanged: distances built for
/// it are distances of the file's mesh too.
bool placed_as_file(const Part& p);

class PartSolids {
 public:
  /// `parts` outlives this; `budget` in bytes (RunOptions::memory_mb).
  PartSolids(const std::vector<Part>& parts, size_t budget) : parts_(parts), cache_(budget) {}

  /// Part p's distances, kept or built (shared by its pairs and threads).
  /// Throws when the part has no triangles.
  std::shared_ptr<const SolidDistance> of(int p);
  /// The same for a part placed as its file (placed_as_file), built (when not
  /// kept) from `file_mesh`, its file's mesh the caller has read already.
  std::shared_ptr<const SolidDistance> of(int p, const Mesh& file_mesh);

  /// Lets part p's distances go: no later pair asks for them. Their large
  /// blocks serve the next build (geometry/huge_page_allocator.h); what the
  /// heap freed goes back to the system (malloc_trim), or each thread's heap
  /// would keep the most its builds ever held (on the 15M scene about
  /// 100 MB more).
  void let_go(int p);

  /// Hands what the cache has dropped since the last call back to the
  /// system (malloc_trim), not to a heap that would keep it resident for the
  /// rest of the run; nothing when it dropped nothing (a trim also gives back
  /// what the next build would take again, page by page).
  void give_back_dropped();

  size_t builds() const { return cache_.builds(); }
  size_t drops() const { return cache_.drops(); }
  size_t peak_bytes() const { return cache_.peak_bytes(); }

 private:
  const std::vector<Part>& parts_;
  ByteCache<int, SolidDistance> cache_;
  std::atomic<size_t> given_back_{0};  ///< drops() at the last trim
};

}  // namespace pd
