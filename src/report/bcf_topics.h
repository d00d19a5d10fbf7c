// Which BCF topics an export holds (--bcf) and their stable GUIDs.
// docs/report-format.md, "BCF".
#pragma once

#include <string>
#include <vector>

#include "report/writer.h"

namespace pd {

/// One BCF topic: the findings it stands for and the key its GUIDs derive from.
struct BcfTopic {
  std::string key;            ///< stable across runs: the group id or the finding's fingerprint
  std::vector<size_t> pairs;  ///< indices into run.pairs; the first one is the topic's view
};

/// Whether a pair needs a person, i.e. gets a topic: an interference or
/// clearance violation (suppressed or not, new or not: the tracker holds its
/// state), a pair not checked or not decided, and any finding that fails the
/// run (a false positive under --fail-on any). Other false positives are the
/// tessellation artefacts pdcheck exists to tell apart: no topic.
bool needs_topic(const PairResult& r, const PairReview& review);

/// The topics of a run, in report order (of each topic's first pair): one per
/// finding group of two or more members (key = the group id, pairs = its
/// members, the deepest first: one item per design problem), and one per
/// other pair that needs_topic (key = its fingerprint, so a lone finding keeps
/// its GUID from night to night). The one place that decides the topics.
std::vector<BcfTopic> bcf_topics(const ReportInput& in);

/// An RFC 9562 UUID, version 8 (custom, hash-based): the first 128 bits of the
/// XXH3-128 of ("pdcheck-bcf-v1", `kind`, `key`) with the version and variant
/// bits set, lowercase as BCF requires. The same key and kind give the same
/// GUID in every run; kinds ("topic", "viewpoint") keep a topic's GUIDs apart.
std::string bcf_guid(const std::string& kind, const std::string& key);

}  // namespace pd
