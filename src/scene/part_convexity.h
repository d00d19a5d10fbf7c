// A pieces auto mesh part's convexity, measured when a pair needs it: the
// parts stage leaves it unset (a part's convexity decides only pairs whose
// hulls interfere, and only when the other part is convex too), and the batch
// stage asks for it there (batch/convexity_on_demand.h).
#pragma once

#include <string>

#include "scene/parts.h"

namespace pd {

/// The part keeps a surface whose convexity is not measured yet.
bool convexity_unmeasured(const Part& p);

/// Measures it (from the convexity cache in `cache_dir` when it holds it, ""
/// for none) and sets p.convex, p.surface->concavity and ->closed: convex when
/// the file's concavity, at this part's stretch, is within its concavity
/// tolerance or the coordinates' noise (as the parts stage decides it for
/// decompose). Reads the surface from the mesh store; throws
/// std::runtime_error when it cannot.
void measure_convexity(Part& p, const std::string& cache_dir);

}  // namespace pd
