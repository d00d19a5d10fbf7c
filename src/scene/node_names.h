// The names of node parts (`"split": "nodes"`, docs/scene-format.md "Split by
// node"): a file's node hierarchy turned into part ids and groups.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pd {

/// A node name as one segment of a `/`-separated path: '%', '/' and '#' are
/// written %25, %2F and %23 (percent-encoding, so the name can be read back and
/// two names never meet in one segment; '#' is kept for repeated names).
std::string escape_node_name(std::string_view name);

/// The path segments of sibling nodes named `names`, in file order: each name
/// escaped, an empty one `node<k>` (k its 0-based position among the siblings),
/// a segment met again suffixed `#2`, `#3`, … in file order.
std::vector<std::string> sibling_segments(const std::vector<std::string>& names);

/// A node part's id: the scene part's id, '/', the node path.
std::string node_part_id(const std::string& part_id, const std::string& node_path);

/// A node part's group: the scene part's group joined with the node path's
/// parent (the path without its last segment); either may be empty.
std::string node_part_group(const std::string& part_group, const std::string& node_path);

}  // namespace pd
