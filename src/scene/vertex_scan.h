// A fast reader for a part's inline vertex list, the bulk of a large scene
// (a 10,000-part assembly is 50 MB of [x, y, z] triples): the general JSON
// parser builds a node per number; this reads the numbers straight into the
// matrix.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "geometry/types.h"

namespace pd {

/// The vertices of `text`, a JSON array of [x, y, z] number triples (white
/// space allowed), as the general parser would read them. std::nullopt on
/// anything else, including an empty list, a number beyond the double range or
/// any syntax error: the caller then runs the general parser, which names the
/// error (this scanner never reports one).
std::optional<Points> scan_vertex_array(std::string_view text);

/// The same into `xyz` (x0 y0 z0 x1 …, cleared first), allocating nothing
/// once `xyz` has grown: for a reader that keeps only a summary of the list.
/// False where scan_vertex_array gives std::nullopt.
bool scan_vertex_array(std::string_view text, std::vector<double>& xyz);

/// The same on the list at the start of `text` (no white space before it),
/// whatever follows it: its length in bytes, or 0 where the above is false.
std::size_t scan_vertex_prefix(std::string_view text, std::vector<double>& xyz);

}  // namespace pd
