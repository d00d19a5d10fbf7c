// Open CASCADE on demand: the code that calls it (reading B-rep files, the
// exact solids) is built into a module, pdcheck_occt.so beside the pdcheck
// binary, that a process loads only when a B-rep file is to be read (not
// taken from the cache) or a pair measured on its solids. Open
// CASCADE and what its toolkits link are 59 of the 87 shared libraries
// pdcheck would otherwise load at every start, and Debian builds them to bind
// every symbol then: a run on mesh files alone started in 0.09 s, most of it
// the dynamic linker's.
//
// read_brep_file and measure_exact_pair (brep_file.h, exact_pair.h) call
// through brep_backend(); a program that links the Open CASCADE code itself
// (the tests) hands it over with use_brep_backend.
#pragma once

#include <string>

#include "brep/brep_file.h"
#include "brep/exact_pair.h"

namespace pd {

/// The calls into Open CASCADE, as the module provides them.
struct BrepBackend {
  BrepFile (*read_file)(const std::string& path, double deflection, int threads) = nullptr;
  ExactMeasure (*measure_pair)(const ExactPart& a, const ExactPart& b,
                               const ExactRequest& r) = nullptr;
};

/// The backend, loading the module on first use (thread-safe). Throws
/// std::runtime_error naming the module, where the build puts it and why it
/// could not be loaded.
const BrepBackend& brep_backend();

/// Loads the module now, so that processes forked later have it without
/// loading it each (a failure is left for brep_backend() to report where the
/// module is needed). Returns whether it is loaded.
bool preload_brep_backend();

/// Makes `backend` the one brep_backend() returns, instead of the module's:
/// for programs linked with the Open CASCADE code (linked_brep_backend()).
void use_brep_backend(const BrepBackend& backend);

/// The name of the module's entry point: `const pd::BrepBackend* (void)`.
inline constexpr const char* kBrepBackendEntry = "pdcheck_occt_backend";
/// The module's file name, looked for beside the running executable.
inline constexpr const char* kBrepModuleName = "pdcheck_occt.so";

}  // namespace pd
