// --html FILE and `pdcheck html`: one self-contained, offline HTML page with the
// report's summary, a table of its findings and a 3D view of each (three.js,
// inlined). Page: src/report/html/; format and caps: docs/report-format.md.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/writer.h"
#include "scene/parts.h"
#include "user_error.h"

namespace pd {

/// The page cannot be made (its inlined library is missing or unreadable).
struct HtmlAssetError : UserError {
  using UserError::UserError;
};

/// Reads the inlined scripts (three.js and its orbit controls, from Debian's
/// libjs-three as found when pdcheck was built, or from the directory in
/// $PDCHECK_THREE_DIR). Throws HtmlAssetError naming the file and the package.
/// Called before a run so that a missing library costs no solve.
void check_html_assets();

/// The page for a JSON report (`report`, as --format json writes it: with the
/// review) and the parts it names (geometry found by id; a part missing from
/// `parts`, or unusable, gets no 3D view and is listed). `notes` are shown on the
/// page (e.g. what could not be read). Throws HtmlAssetError.
std::string render_html(const nlohmann::ordered_json& report, const std::vector<Part>& parts,
                        const std::vector<std::string>& notes = {});

/// The page of a run (--html FILE).
std::string render_html(const ReportInput& in);

}  // namespace pd
