#include "brep/occt_backend.h"

namespace pd {

const BrepBackend& linked_brep_backend() {
  static const BrepBackend backend{&occt_read_brep_file, &occt_measure_exact_pair};
  return backend;
}

}  // namespace pd
