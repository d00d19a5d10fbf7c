// A fast reader for a part's inline vertex list, the bulk of a large scene
// (a 10,000-part assembly is 50 MB of [x, y, z] triples): the general JSON
// parser builds a node per number; this reads the numbers straight into the
// matrix.
#pragma once

#include <optional>
#include <string_view>

#include "geometry/types.h"

namespace pd {

/// The vertices of `text`, a JSON array of [x, y, z] number triples (white
/// space allowed), as the general parser would read them. std::nullopt on
/// anything else, including an empty list, a number beyond the double range or
/// any syntax error: the caller then runs the general parser, which names the
/// error (this scanner never reports one).
std::optional<Points> scan_vertex_array(std::string_view text);

}  // namespace pd
