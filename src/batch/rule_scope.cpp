#include "batch/rule_scope.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <unordered_map>

#include "hash.h"

namespace pd {

namespace {

std::uint64_t key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

std::vector<int> every_part(const SceneSpec& scene, std::vector<int> loaded) {
  if (loaded.empty()) {
    loaded.resize(scene.parts.size());
    std::iota(loaded.begin(), loaded.end(), 0);
  }
  return loaded;
}

}  // namespace

RuleScope::RuleScope(const SceneSpec& scene, std::vector<int> loaded)
    : start_(std::chrono::steady_clock::now()),
      rules_(std::make_shared<const Rules>(*scene.rules)),
      index_(*rules_, scene.parts),
      loaded_(every_part(scene, std::move(loaded))) {
  coverage_.rules = rules_;
  coverage_.hash = rules_hash(scene);
  if (scene.checks.clearance) {
    std::unordered_map<std::string, int> index;
    for (size_t k = 0; k < scene.parts.size(); ++k) index.emplace(scene.parts[k].id, int(k));
    for (const auto& e : scene.checks.clearance->pairs)
      own_clearance_.insert(key(index.at(e.a), index.at(e.b)));
  }
  coverage_.set_parts = index_.set_parts();
  coverage_.test_pairs.assign(rules_->tests.size(), 0);
  coverage_.ignore_pairs.assign(rules_->ignore.size(), 0);
  coverage_.expected_pairs.assign(rules_->expected.size(), 0);
  coverage_.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void RuleScope::apply(CandidatePairs& c) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::pair<int, int>> kept;
  kept.reserve(c.pairs.size());
  PairDecision d;  // one decision's storage for every pair
  for (const auto& [a, b] : c.pairs) {
    index_.decide(loaded_[a], loaded_[b], d);
    if (d.scope == PairDecision::Scope::kOutOfScope) {
      ++coverage_.out_of_scope;
      continue;
    }
    if (d.scope == PairDecision::Scope::kIgnored) {
      ++coverage_.ignored;
      ++coverage_.ignore_pairs[d.ignore];
      continue;
    }
    for (int t : d.tests) ++coverage_.test_pairs[t];
    if (d.expected >= 0) ++coverage_.expected_pairs[d.expected];
    Kept k{d.tolerance,
           d.clearance,
           d.tolerance_test,
           d.tolerance_pair,
           d.clearance_rank,
           d.expected,
           std::uint32_t(tests_.size()),
           0};
    tests_.insert(tests_.end(), d.tests.begin(), d.tests.end());
    k.tests_end = std::uint32_t(tests_.size());
    kept.emplace_back(a, b);
    keys_.push_back(key(a, b));
    kept_.push_back(k);
  }
  c.pairs = std::move(kept);
  // Candidates come sorted by (a, b), so keys_ is; sorted again for any other caller.
  if (!std::is_sorted(keys_.begin(), keys_.end())) {
    std::vector<size_t> order(keys_.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return keys_[x] < keys_[y]; });
    std::vector<std::uint64_t> keys;
    std::vector<Kept> decisions;
    for (size_t o : order) keys.push_back(keys_[o]), decisions.push_back(kept_[o]);
    keys_ = std::move(keys);
    kept_ = std::move(decisions);
  }
  coverage_.seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

const RuleScope::Kept* RuleScope::decision(int a, int b) const {
  const std::uint64_t k = key(a, b);
  const auto it = std::lower_bound(keys_.begin(), keys_.end(), k);
  return it == keys_.end() || *it != k ? nullptr : &kept_[size_t(it - keys_.begin())];
}

std::function<PairChecks(int, int)> RuleScope::pair_checks(
    std::function<PairChecks(int, int)> base) const {
  return [this, base = std::move(base)](int a, int b) {
    PairChecks pc = base(a, b);
    const Kept* d = decision(a, b);
    if (!d) return pc;
    // Scene -> test -> pair: a rule's tolerance replaces the scene's (or its
    // auto band); the pair's own was already preferred by decide().
    if (d->tolerance) {
      PairDecision named;
      named.tolerance_test = d->tolerance_test;
      named.tolerance_pair = d->tolerance_pair;
      pc.tolerance = PairTolerance{};
      pc.tolerance->value = *d->tolerance;
      pc.tolerance->source = "rule";
      pc.tolerance->basis = index_.tolerance_rule(named);
    }
    // checks.clearance.pairs names a pair as rules.pairs does (pair rank):
    // between the two the larger minimum wins; over a test's, the pair's.
    if (d->clearance && pc.clearance) {
      const bool own = own_clearance_.count(key(loaded_[a], loaded_[b])) > 0;
      if (!own)
        pc.clearance = *d->clearance;
      else if (d->clearance_rank == 2)
        pc.clearance = std::max(*pc.clearance, *d->clearance);
    }
    return pc;
  };
}

void RuleScope::note(PairResult& r) const {
  const Kept* d = decision(r.a, r.b);
  if (!d) return;
  r.tests.clear();
  for (auto t = d->tests_begin; t < d->tests_end; ++t)
    r.tests.push_back(rules_->tests[tests_[t]].name);
  r.expected = d->expected >= 0 ? rules_->expected[d->expected].name : "";
}

std::string rules_hash(const SceneSpec& scene) {
  Hasher h;
  h.add("rules").add(scene.rules ? scene.rules->canonical : "");
  for (const PartSpec& p : scene.parts) {
    h.add(p.id).add(p.group).add(p.mesh.value_or(""));
    h.add(std::to_string(p.tags.size()));
    for (const std::string& t : p.tags) h.add(t);
  }
  return h.hex();
}

}  // namespace pd
