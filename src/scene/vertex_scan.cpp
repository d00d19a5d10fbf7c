#include "scene/vertex_scan.h"

#include <charconv>
#include <cmath>
#include <vector>

namespace pd {

namespace {

struct Cursor {
  const char* p;
  const char* end;

  void skip_space() {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
  }
  bool take(char c) {
    skip_space();
    if (p == end || *p != c) return false;
    ++p;
    return true;
  }
  static bool digit(char c) { return c >= '0' && c <= '9'; }

  /// One number in JSON's own grammar (from_chars alone would also take
  /// "1." or "inf"): -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
  bool number(double& out) {
    skip_space();
    const char* b = p;
    const char* q = p;
    if (q < end && *q == '-') ++q;
    if (q == end || !digit(*q)) return false;
    if (*q == '0')
      ++q;
    else
      while (q < end && digit(*q)) ++q;
    bool integer = true;
    if (q < end && *q == '.') {
      integer = false;
      ++q;
      if (q == end || !digit(*q)) return false;
      while (q < end && digit(*q)) ++q;
    }
    if (q < end && (*q == 'e' || *q == 'E')) {
      integer = false;
      ++q;
      if (q < end && (*q == '+' || *q == '-')) ++q;
      if (q == end || !digit(*q)) return false;
      while (q < end && digit(*q)) ++q;
    }
    const auto r = std::from_chars(b, q, out);
    if (r.ec != std::errc() || r.ptr != q || !std::isfinite(out)) return false;
    // The general parser reads "-0" as the integer 0, whose double is +0.
    if (integer && out == 0) out = 0.0;
    p = q;
    return true;
  }
};

}  // namespace

namespace {

/// Reads the list from c.p on; false on anything but a plain list.
bool scan_list(Cursor& c, std::vector<double>& xyz) {
  xyz.clear();
  if (!c.take('[')) return false;
  while (true) {
    if (!c.take('[')) return false;
    for (int d = 0; d < 3; ++d) {
      double v;
      if ((d > 0 && !c.take(',')) || !c.number(v)) return false;
      xyz.push_back(v);
    }
    if (!c.take(']')) return false;
    if (c.take(']')) return true;
    if (!c.take(',')) return false;
  }
}

}  // namespace

bool scan_vertex_array(std::string_view text, std::vector<double>& xyz) {
  Cursor c{text.data(), text.data() + text.size()};
  if (!scan_list(c, xyz)) return false;
  c.skip_space();
  return c.p == c.end;
}

std::size_t scan_vertex_prefix(std::string_view text, std::vector<double>& xyz) {
  if (text.empty() || text[0] != '[') return 0;
  Cursor c{text.data(), text.data() + text.size()};
  if (!scan_list(c, xyz)) return 0;
  return static_cast<std::size_t>(c.p - text.data());
}

std::optional<Points> scan_vertex_array(std::string_view text) {
  // One buffer per thread, kept between parts: a fresh one per part was
  // allocated and faulted in again each time.
  thread_local std::vector<double> xyz;
  if (!scan_vertex_array(text, xyz)) return std::nullopt;
  // Points is column-major: x0 y0 z0 x1 … is its memory layout.
  return Points(Eigen::Map<const Points>(xyz.data(), 3, static_cast<Eigen::Index>(xyz.size() / 3)));
}

}  // namespace pd
