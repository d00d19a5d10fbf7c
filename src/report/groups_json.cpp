#include "report/groups_json.h"

#include "results/fingerprint.h"

namespace pd {

using json = nlohmann::ordered_json;

namespace {

std::string fingerprint_of(const RunResult& run, size_t k) {
  const PairResult& r = run.pairs[k];
  return pair_fingerprint(run.parts[r.a].id, run.parts[r.b].id);
}

}  // namespace

json groups_json(const FindingGroups& groups, const RunResult& run) {
  json out = json::array();
  for (const FindingGroup& g : groups.groups) {
    json members = json::array(), parts = json::array(), covers = json::array();
    for (size_t k : g.members)
      members.push_back({{"fingerprint", fingerprint_of(run, k)},
                         {"a", run.parts[run.pairs[k].a].id},
                         {"b", run.parts[run.pairs[k].b].id},
                         {"status", status_name(run.pairs[k].status)}});
    for (int p : g.parts) parts.push_back(run.parts[p].id);
    for (size_t k : g.move.covers) covers.push_back(fingerprint_of(run, k));
    const Vec3& d = g.move.direction;
    out.push_back({{"id", g.id},
                   {"members", members},
                   {"parts", parts},
                   {"deepest", fingerprint_of(run, g.deepest)},
                   {"depth", run.pairs[g.deepest].depth},
                   {"depth_source", run.pairs[g.deepest].depth_source},
                   {"move",
                    {{"part", run.parts[g.move.part].id},
                     {"direction", {d.x() + 0.0, d.y() + 0.0, d.z() + 0.0}},
                     {"length", g.move.length},
                     {"covers", covers}}}});
  }
  return out;
}

}  // namespace pd
