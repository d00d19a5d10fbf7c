#include "report/bcf_topics.h"

#include "hash.h"

namespace pd {

bool needs_topic(const PairResult& r, const PairReview& review) {
  return r.status == Status::kInterference || r.status == Status::kClearanceViolation ||
         not_decided(r.status) || review.fails;
}

std::vector<BcfTopic> bcf_topics(const ReportInput& in) {
  const FindingGroups& groups = in.review.groups;
  std::vector<BcfTopic> topics;
  std::vector<char> done(groups.groups.size(), 0);
  for (size_t k = 0; k < in.run.pairs.size(); ++k) {
    if (!needs_topic(in.run.pairs[k], in.review.pairs[k])) continue;
    const int g = k < groups.group_of.size() ? groups.group_of[k] : -1;
    if (g < 0 || groups.groups[g].members.size() < 2) {
      topics.push_back({in.review.pairs[k].fingerprint, {k}});
      continue;
    }
    if (done[g]) continue;  // the group's topic is where its first member is
    done[g] = 1;
    const FindingGroup& group = groups.groups[g];
    BcfTopic t{group.id, {group.deepest}};
    for (const size_t m : group.members)
      if (m != group.deepest) t.pairs.push_back(m);
    topics.push_back(std::move(t));
  }
  return topics;
}

std::string bcf_guid(const std::string& kind, const std::string& key) {
  Hasher h;
  h.add("pdcheck-bcf-v1").add(kind).add(key);
  std::string x = h.hex();  // 32 lowercase hex digits
  static const char* kHex = "0123456789abcdef";
  const auto nibble = [](char c) { return c <= '9' ? c - '0' : c - 'a' + 10; };
  x[12] = '8';                            // version 8
  x[16] = kHex[8 | (nibble(x[16]) & 3)];  // variant 10xx
  return x.substr(0, 8) + "-" + x.substr(8, 4) + "-" + x.substr(12, 4) + "-" + x.substr(16, 4) +
         "-" + x.substr(20, 12);
}

}  // namespace pd
