#include "scene/rule_index.h"

#include <algorithm>
#include <map>
#include <unordered_set>

#include "scene/rule_glob.h"

namespace pd {

namespace {

/// A set's patterns, split into exact names (hashed) and globs (matched).
struct Matcher {
  std::unordered_set<std::string> exact_ids, tags;
  std::vector<std::string> id_globs;
  std::vector<std::vector<std::string_view>> groups;  ///< split once (into the set's own strings)
  explicit Matcher(const RuleSet& s) : tags(s.tags.begin(), s.tags.end()) {
    for (const std::string& g : s.groups) groups.push_back(group_segments(g));
    for (const std::string& p : s.ids) {
      if (has_wildcard(p))
        id_globs.push_back(p);
      else
        exact_ids.insert(p);
    }
  }
  bool operator()(const PartSpec& p, const std::vector<std::string_view>& group) const {
    if (exact_ids.count(p.id)) return true;
    for (const std::string& g : id_globs)
      if (glob_match(g, p.id)) return true;
    for (const std::string& t : p.tags)
      if (tags.count(t)) return true;
    for (const auto& g : groups)
      if (group_segments_match(g, group)) return true;
    return false;
  }
};

std::uint64_t key(int i, int j) {
  if (i > j) std::swap(i, j);
  return (std::uint64_t(std::uint32_t(i)) << 32) | std::uint32_t(j);
}

}  // namespace

RuleIndex::RuleIndex(const Rules& rules, const std::vector<PartSpec>& parts) : rules_(&rules) {
  const size_t n = parts.size(), sets = rules.sets.size();
  words_ = std::max<size_t>(1, (sets + 63) / 64);
  bits_.assign(n * words_, 0);
  set_parts_.assign(sets, 0);
  std::vector<std::vector<std::string_view>> paths(n);  // each part's group, split once
  for (size_t k = 0; k < n; ++k) paths[k] = group_segments(parts[k].group);
  for (size_t s = 0; s < sets; ++s) {
    const Matcher m(rules.sets[s]);
    for (size_t k = 0; k < n; ++k)
      if (m(parts[k], paths[k])) {
        bits_[k * words_ + s / 64] |= std::uint64_t(1) << (s % 64);
        ++set_parts_[s];
      }
    if (set_parts_[s] == 0 && !rules.sets[s].optional)
      throw SceneError(rules.sets[s].where + ": the set \"" + rules.sets[s].name +
                       "\" selects no part (check its ids, tags and groups against the "
                       "parts, or mark it \"optional\": true)");
  }
  std::map<std::string, int> groups, files;
  group_.assign(n, -1);
  file_.assign(n, -1);
  for (size_t k = 0; k < n; ++k) {
    if (!parts[k].group.empty())
      group_[k] = groups.emplace(parts[k].group, int(groups.size())).first->second;
    if (parts[k].mesh) file_[k] = files.emplace(*parts[k].mesh, int(files.size())).first->second;
  }
  if (!rules.pairs.empty()) {
    std::unordered_map<std::string, int> index;
    for (size_t k = 0; k < n; ++k) index.emplace(parts[k].id, int(k));
    for (size_t r = 0; r < rules.pairs.size(); ++r) {
      const PairRule& p = rules.pairs[r];
      for (const std::string& id : {p.a, p.b})
        if (!index.count(id)) throw SceneError(p.where + ": unknown part id \"" + id + "\"");
      if (!pair_rule_.emplace(key(index[p.a], index[p.b]), int(r)).second)
        throw SceneError(p.where + ": the pair " + p.a + " / " + p.b + " is listed twice");
    }
  }
}

bool RuleIndex::covers(const SetPair& s, int i, int j) const {
  if (s.self()) return in_set(i, s.a) && in_set(j, s.a);
  return (in_set(i, s.a) && in_set(j, s.b)) || (in_set(i, s.b) && in_set(j, s.a));
}

PairDecision RuleIndex::decide(int i, int j) const {
  PairDecision d;
  decide(i, j, d);
  return d;
}

void RuleIndex::decide(int i, int j, PairDecision& d) const {
  const Rules& r = *rules_;
  d.tests.clear();  // its capacity kept: one decision object serves every pair
  d.scope = PairDecision::Scope::kChecked;
  d.ignore = d.expected = d.tolerance_test = d.tolerance_pair = -1;
  d.tolerance.reset();
  d.clearance.reset();
  d.clearance_rank = 0;
  for (size_t t = 0; t < r.tests.size(); ++t) {
    const RuleTest& test = r.tests[t];
    if (!covers(test.sets, i, j)) continue;
    d.tests.push_back(int(t));
    // Equal rank: the stricter wins (the smaller tolerance, the larger clearance).
    if (test.tolerance && (!d.tolerance || *test.tolerance < *d.tolerance)) {
      d.tolerance = test.tolerance;
      d.tolerance_test = int(t);
    }
    if (test.clearance && (!d.clearance || *test.clearance > *d.clearance)) {
      d.clearance = test.clearance;
      d.clearance_rank = 1;
    }
  }
  if (!r.tests.empty() && d.tests.empty()) {
    d.scope = PairDecision::Scope::kOutOfScope;
    return;
  }
  for (size_t g = 0; g < r.ignore.size(); ++g) {
    const IgnoreRule& rule = r.ignore[g];
    bool hit = false;
    if (rule.same == IgnoreRule::Same::kGroup)
      hit = group_[i] >= 0 && group_[i] == group_[j];
    else if (rule.same == IgnoreRule::Same::kFile)
      hit = file_[i] >= 0 && file_[i] == file_[j];
    else
      hit = covers(rule.sets, i, j);
    if (hit) {
      d.scope = PairDecision::Scope::kIgnored;
      d.ignore = int(g);
      return;
    }
  }
  for (size_t e = 0; e < r.expected.size() && d.expected < 0; ++e)
    if (covers(r.expected[e].sets, i, j)) d.expected = int(e);
  if (!pair_rule_.empty()) {  // the most specific level: the pair's own
    const auto it = pair_rule_.find(key(i, j));
    if (it != pair_rule_.end()) {
      const PairRule& p = r.pairs[it->second];
      if (p.tolerance) {
        d.tolerance = p.tolerance;
        d.tolerance_pair = it->second;
        d.tolerance_test = -1;
      }
      if (p.clearance) {
        d.clearance = p.clearance;
        d.clearance_rank = 2;
      }
    }
  }
}

std::string RuleIndex::tolerance_rule(const PairDecision& d) const {
  if (d.tolerance_pair >= 0) return "pairs[" + std::to_string(d.tolerance_pair) + "]";
  if (d.tolerance_test >= 0) return "tests[\"" + rules_->tests[d.tolerance_test].name + "\"]";
  return "";
}

std::vector<std::string> RuleIndex::sets_of(int part) const {
  std::vector<std::string> out;
  for (size_t s = 0; s < rules_->sets.size(); ++s)
    if (in_set(part, int(s))) out.push_back(rules_->sets[s].name);
  return out;
}

}  // namespace pd
