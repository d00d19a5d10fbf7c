// The entry point of pdcheck_occt.so (brep/brep_backend.h): the one symbol the
// module exports; everything else in it, Open CASCADE's callers and the
// pdcheck code they use, stays private to it.
#include "brep/occt_backend.h"

extern "C" __attribute__((visibility("default"))) const pd::BrepBackend* pdcheck_occt_backend() {
  return &pd::linked_brep_backend();
}
