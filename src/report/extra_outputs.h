// The files a run or a merge writes beside its report: --junit, --sarif, --html,
// --csv, --bcf and --write-suppressions. Every path is checked before the work (a bad one
// fails in a second, not after hours of solving) and written after it, each
// whole or not at all (output_file.h).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "report/output_file.h"
#include "report/writer.h"

namespace pd {

/// The paths as given on the command line (nullopt = not asked for).
struct ExtraOutputPaths {
  std::optional<std::string> junit, sarif, html, write_suppressions;
  std::optional<std::string> csv, bcf;
};

struct ExtraOutputs {
  std::optional<OutputFile> junit, sarif, html, write_suppressions;
  std::optional<OutputFile> csv, bcf;
};

/// Checks every path, and that the HTML page can be made when it is asked for.
/// Throws OutputError or HtmlAssetError.
ExtraOutputs check_extra_outputs(const ExtraOutputPaths& paths);

/// Writes each file asked for. `html_page` renders the page (a run has its
/// parts' geometry at hand; a merge reads it again). Throws OutputError or
/// HtmlAssetError.
void write_extra_outputs(const ExtraOutputs& out, const ReportInput& report,
                         const std::function<std::string()>& html_page);

}  // namespace pd
