// The CI options of a run and of a merge (docs/ci.md): --fail-on, --baseline,
// --suppressions, the extra outputs.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "report/extra_outputs.h"
#include "report/review_inputs.h"

struct CiOptions {
  pd::ReviewArgs review;
  std::string write_suppressions, junit, sarif, html, csv, bcf;
};

void add_ci_options(CLI::App& app, CiOptions& o);

/// The extra outputs asked for on `app` (an option given, even as "", is asked for).
pd::ExtraOutputPaths extra_output_paths(const CLI::App& app, const CiOptions& o);
