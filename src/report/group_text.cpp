#include "report/group_text.h"

#include "report/finding_text.h"

namespace pd {

namespace {

constexpr size_t kShownGroups = 10, kShownParts = 5;

std::string vector_text(const Vec3& v) {
  return "(" + short_number(v.x() + 0.0) + ", " + short_number(v.y() + 0.0) + ", " +
         short_number(v.z() + 0.0) + ")";
}

}  // namespace

std::string group_lines(const ReportInput& in) {
  const std::string& units = in.context.units;
  const auto& parts = in.run.parts;
  std::string out;
  size_t several = 0;
  for (const FindingGroup& g : in.review.groups.groups) {
    if (g.members.size() < 2 || ++several > kShownGroups) continue;
    std::string names;
    for (size_t n = 0; n < g.parts.size() && n < kShownParts; ++n)
      names += (n ? ", " : "") + parts[g.parts[n]].id;
    if (g.parts.size() > kShownParts) names += ", …";
    const PairResult& deepest = in.run.pairs[g.deepest];
    out += "pdcheck: group " + g.id.substr(0, 8) + ": " + std::to_string(g.members.size()) +
           " findings (" + names + "): moving " + parts[g.move.part].id + " by " +
           short_number(g.move.length) + " " + units + " along " + vector_text(g.move.direction) +
           " clears " + std::to_string(g.move.covers.size()) + " of them; deepest " +
           parts[deepest.a].id + " / " + parts[deepest.b].id + ", " +
           depth_meaning(deepest.depth_source) + " " + short_number(deepest.depth) + " " + units +
           "\n";
  }
  if (several > kShownGroups)
    out += "pdcheck: … and " + std::to_string(several - kShownGroups) +
           " more groups of several findings (the report's groups list each)\n";
  return out;
}

}  // namespace pd
