#include "scene/rule_glob.h"

#include <vector>

namespace pd {

namespace {

// Iterative glob with one backtrack point: linear in practice, never
// exponential (the last `*` absorbs what the text has left over).
bool match(std::string_view p, std::string_view t, bool cross_slash) {
  size_t pi = 0, ti = 0, star = std::string_view::npos, mark = 0;
  while (ti < t.size()) {
    if (pi < p.size() && p[pi] == '*') {
      star = pi++;
      mark = ti;
    } else if (pi < p.size() &&
               (p[pi] == t[ti] || (p[pi] == '?' && (cross_slash || t[ti] != '/')))) {
      ++pi, ++ti;
    } else if (star != std::string_view::npos && (cross_slash || t[mark] != '/')) {
      pi = star + 1;
      ti = ++mark;
    } else {
      return false;
    }
  }
  while (pi < p.size() && p[pi] == '*') ++pi;
  return pi == p.size();
}

}  // namespace

std::vector<std::string_view> group_segments(std::string_view s) {
  std::vector<std::string_view> out;
  size_t b = 0;
  for (size_t k = 0; k <= s.size(); ++k)
    if (k == s.size() || s[k] == '/') {
      out.push_back(s.substr(b, k - b));
      b = k + 1;
    }
  return out;
}

namespace {

// Pattern segments [p, ...) against path segments [g, ...); the path may go
// on past the pattern's end (a prefix of segments matches).
bool match_segments(const std::vector<std::string_view>& ps, size_t p,
                    const std::vector<std::string_view>& gs, size_t g) {
  if (p == ps.size()) return true;
  if (ps[p] == "**") {
    for (size_t k = g; k <= gs.size(); ++k)
      if (match_segments(ps, p + 1, gs, k)) return true;
    return false;
  }
  return g < gs.size() && match(ps[p], gs[g], false) && match_segments(ps, p + 1, gs, g + 1);
}

}  // namespace

bool glob_match(std::string_view pattern, std::string_view text) {
  return match(pattern, text, true);
}

bool group_glob_match(std::string_view pattern, std::string_view group) {
  if (group.empty()) return false;
  return match_segments(group_segments(pattern), 0, group_segments(group), 0);
}

bool group_segments_match(const std::vector<std::string_view>& pattern,
                          const std::vector<std::string_view>& group) {
  if (group.empty() || (group.size() == 1 && group[0].empty())) return false;
  return match_segments(pattern, 0, group, 0);
}

bool has_wildcard(std::string_view pattern) {
  return pattern.find_first_of("*?") != std::string_view::npos;
}

}  // namespace pd
