// The pdcheck command line as a function: the pdcheck executable runs it
// (pdcheck.cpp), and so does the tests' fault-injecting one
// (tests/pdcheck_faults.cpp).
#pragma once

#include "batch/run.h"

/// Parses the arguments, runs the command and returns the exit code. `faults`:
/// fault injection into the run's worker processes, for tests; empty in the product.
int run_cli(int argc, char** argv, const pd::FaultHooks& faults);
