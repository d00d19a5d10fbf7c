// The globs of rule sets (scene/rules.h, docs/scene-format.md "Rules").
#pragma once

#include <string_view>

namespace pd {

/// `*` matches any run of characters (`/` included), `?` any one character;
/// everything else itself. For part ids.
bool glob_match(std::string_view pattern, std::string_view text);

/// Over `/`-separated group paths, segment by segment: within a segment `*`
/// and `?` as glob_match (never crossing `/`), a segment `**` matches any
/// number of segments. A pattern that matches the leading segments of a path
/// matches the path: selecting an assembly selects what is under it
/// ("wing/rib-*" matches "wing/rib-7/bracket").
bool group_glob_match(std::string_view pattern, std::string_view group);

/// Whether `pattern` holds a wildcard (`*` or `?`): else it names one string.
bool has_wildcard(std::string_view pattern);

}  // namespace pd
