// A pieces auto mesh part's convexity, measured when a pair needs it: the
// parts stage leaves it unset (a part's convexity decides only pairs whose
// hulls interfere, and only when the other part is convex too), and the batch
// stage asks for it there (batch/convexity_on_demand.h).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "geometry/mesh_intersect.h"
#include "scene/convexity_cache.h"
#include "scene/parts.h"

namespace pd {

/// The part keeps a surface whose convexity is not measured yet.
bool convexity_unmeasured(const Part& p);

/// What measuring the part's file at the part's stretch is keyed by: every
/// instance of one file at one stretch gets the same measurement.
std::string convexity_key_of(const Part& p);

/// The file's concavity and closedness at the part's stretch (file units),
/// from the convexity cache in `cache_dir` when it holds them ("" for none),
/// else measured on the file's mesh from the mesh store (its distinct
/// positions hulled in file coordinates, so the answer does not depend on
/// which instance asks) and cached. Throws std::runtime_error when the
/// surface cannot be read. `prepared`, when given, returns the file's mesh
/// (the argument, as read) prepared for distances (geometry/mesh_intersect.h)
/// where the caller keeps one (else null): the measure then builds none of
/// its own.
StoredConvexity measure_file_convexity(
    const Part& p, const std::string& cache_dir,
    const std::function<std::shared_ptr<const PreparedMesh>(const Mesh&)>& prepared = {});

/// Whether `c`, the part's file measured, makes the part convex (set_convexity's verdict).
bool convex_by(const Part& p, const StoredConvexity& c);

/// Sets p.convex, p.surface->concavity and ->closed from `c`: convex when the
/// file's concavity, at this part's stretch, is within its concavity tolerance
/// or the coordinates' noise (as the parts stage decides it for decompose).
void set_convexity(Part& p, const StoredConvexity& c);

/// Both: measures the part and sets what it found.
void measure_convexity(Part& p, const std::string& cache_dir);

}  // namespace pd
