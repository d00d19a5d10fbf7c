// The globs of rule sets (scene/rules.h, docs/scene-format.md "Rules").
#pragma once

#include <string_view>
#include <vector>

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

/// A group path or pattern split at '/', for group_segments_match: split once,
/// matched against many.
std::vector<std::string_view> group_segments(std::string_view path);
/// group_glob_match on paths already split by group_segments (an empty group: no match).
bool group_segments_match(const std::vector<std::string_view>& pattern,
                          const std::vector<std::string_view>& group);

/// Whether `pattern` holds a wildcard (`*` or `?`): else it names one string.
bool has_wildcard(std::string_view pattern);

}  // namespace pd
