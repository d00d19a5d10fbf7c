#include "report/warning_lines.h"

#include <map>

#include "scene/setup_warnings.h"

namespace pd {

std::vector<std::string> warning_lines(const RunResult& run) {
  std::vector<std::string> lines;
  struct Kind {
    std::string first;  ///< the first occurrence, named
    long more = 0;
  };
  std::vector<std::string> order;
  std::map<std::string, Kind> kinds;
  auto note = [&](const std::string& who, const std::string& w) {
    const auto kind = setup_warning_kind(w);
    if (!kind) {
      lines.push_back(who + ": " + w);
      return;
    }
    auto [it, fresh] = kinds.emplace(*kind, Kind{});
    if (fresh) {
      order.push_back(*kind);
      // "kind: part "a": the rest" reads as the kind first, then who.
      it->second.first = *kind + ": " + who + ": " + w.substr(kind->size() + 2);
    } else {
      ++it->second.more;
    }
  };
  for (const Part& p : run.parts)
    for (const auto& w : p.warnings) note("part \"" + p.id + "\"", w);
  for (const PairResult& r : run.pairs) {
    if (r.a < 0 || r.b < 0 || size_t(r.a) >= run.parts.size() || size_t(r.b) >= run.parts.size())
      continue;
    for (const auto& w : r.warnings)
      if (setup_warning_kind(w)) note(run.parts[r.a].id + " / " + run.parts[r.b].id, w);
  }
  for (const auto& k : order) {
    const Kind& kind = kinds[k];
    lines.push_back(kind.first + (kind.more ? " (and " + std::to_string(kind.more) +
                                                  " more: the report's warnings list each)"
                                            : ""));
  }
  return lines;
}

}  // namespace pd
