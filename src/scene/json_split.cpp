#include "scene/json_split.h"

namespace pd {

namespace {

// A cursor over the text; every step returns false on a structure it cannot read.
struct Scanner {
  std::string_view t;
  std::size_t pos = 0;

  bool at_end() const { return pos >= t.size(); }
  char peek() const { return at_end() ? '\0' : t[pos]; }

  void skip_space() {
    while (!at_end() && (t[pos] == ' ' || t[pos] == '\t' || t[pos] == '\n' || t[pos] == '\r'))
      ++pos;
  }

  bool expect(char c) {
    skip_space();
    if (peek() != c) return false;
    ++pos;
    return true;
  }

  /// At an opening quote: moves past the closing one.
  bool skip_string() {
    for (++pos; pos < t.size(); ++pos) {
      if (t[pos] == '\\')
        ++pos;  // the escaped character cannot close the string
      else if (t[pos] == '"') {
        ++pos;
        return true;
      }
    }
    return false;
  }

  /// Moves past one value: a string, an object or array (to its matching
  /// bracket), or a scalar (to the next delimiter).
  bool skip_value() {
    skip_space();
    const char c = peek();
    if (c == '"') return skip_string();
    if (c == '{' || c == '[') {
      int depth = 0;
      while (pos < t.size()) {
        const char d = t[pos];
        if (d == '"') {
          if (!skip_string()) return false;
          continue;
        }
        if (d == '{' || d == '[') ++depth;
        if (d == '}' || d == ']') --depth;
        ++pos;
        if (depth == 0) return true;
      }
      return false;
    }
    const std::size_t start = pos;
    while (!at_end() && t[pos] != ',' && t[pos] != '}' && t[pos] != ']' && t[pos] != ' ' &&
           t[pos] != '\t' && t[pos] != '\n' && t[pos] != '\r')
      ++pos;
    return pos > start;
  }

  bool array_elements(ArraySpan& out) {
    out.begin = pos;
    ++pos;  // '['
    skip_space();
    if (peek() == ']') {
      out.end = ++pos;
      return true;
    }
    while (true) {
      skip_space();
      const std::size_t b = pos;
      if (!skip_value()) return false;
      out.elements.emplace_back(b, pos);
      skip_space();
      if (peek() == ']') {
        out.end = ++pos;
        return true;
      }
      if (!expect(',')) return false;
    }
  }
};

}  // namespace

namespace {

/// `read`, when given, reads the array (read_top_level_array).
std::optional<ArraySpan> find_array(std::string_view text, std::string_view key,
                                    const std::function<std::size_t(std::string_view)>* read) {
  Scanner s{text};
  if (!s.expect('{')) return std::nullopt;
  std::optional<ArraySpan> found;
  s.skip_space();
  if (s.peek() == '}') return std::nullopt;
  while (true) {
    s.skip_space();
    if (s.peek() != '"') return std::nullopt;
    const std::size_t k0 = s.pos;
    if (!s.skip_string()) return std::nullopt;
    // The raw key between the quotes. A key with an escape may spell `key`
    // ("par\u0074s"): the scan cannot tell, so the whole-text parse decides.
    const std::string_view name = text.substr(k0 + 1, s.pos - k0 - 2);
    if (name.find('\\') != std::string_view::npos) return std::nullopt;
    if (!s.expect(':')) return std::nullopt;
    s.skip_space();
    if (name == key) {
      if (found || s.peek() != '[') return std::nullopt;  // duplicate, or not an array
      found.emplace();
      if (read) {
        const std::size_t n = (*read)(text.substr(s.pos));
        if (n == 0) return std::nullopt;
        found->begin = s.pos;
        s.pos += n;
        found->end = s.pos;
      } else if (!s.array_elements(*found)) {
        return std::nullopt;
      }
    } else if (!s.skip_value()) {
      return std::nullopt;
    }
    s.skip_space();
    if (s.peek() == '}') {
      ++s.pos;
      break;
    }
    if (!s.expect(',')) return std::nullopt;
  }
  s.skip_space();
  if (!s.at_end()) return std::nullopt;
  return found;
}

}  // namespace

std::optional<ArraySpan> top_level_array(std::string_view text, std::string_view key) {
  return find_array(text, key, nullptr);
}

std::optional<ArraySpan> read_top_level_array(
    std::string_view text, std::string_view key,
    const std::function<std::size_t(std::string_view)>& read) {
  return find_array(text, key, &read);
}

}  // namespace pd
