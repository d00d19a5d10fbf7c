// The Open CASCADE implementations behind brep/brep_backend.h: built into the
// module (occt_module.cpp) and into programs that link them directly.
#pragma once

#include <string>

#include "brep/brep_backend.h"

namespace pd {

BrepFile occt_read_brep_file(const std::string& path, double deflection, int threads);
ExactMeasure occt_measure_exact_pair(const ExactPart& a, const ExactPart& b, const ExactRequest& r);

/// The backend of the code linked into this program.
const BrepBackend& linked_brep_backend();

}  // namespace pd
