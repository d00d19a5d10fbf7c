#include "scene/json_split.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pd {

namespace {

// The first position at or after `i` holding one of the bytes `a`..`e` (repeat
// one to look for fewer), else a position >= t.size(). Sixteen bytes a step
// where SSE2 is there: a shard's scan walks every byte of a 50 MB scene, and a
// byte at a time that walk was a quarter of its fixed cost.
template <char a, char b, char c = a, char d = a, char e = a>
std::size_t next_of(std::string_view t, std::size_t i) {
#if defined(__SSE2__)
  const __m128i va = _mm_set1_epi8(a), vb = _mm_set1_epi8(b), vc = _mm_set1_epi8(c),
                vd = _mm_set1_epi8(d), ve = _mm_set1_epi8(e);
  for (; i + 16 <= t.size(); i += 16) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(t.data() + i));
    const __m128i hit =
        _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi8(v, va), _mm_cmpeq_epi8(v, vb)),
                     _mm_or_si128(_mm_cmpeq_epi8(v, vc),
                                  _mm_or_si128(_mm_cmpeq_epi8(v, vd), _mm_cmpeq_epi8(v, ve))));
    if (const int bits = _mm_movemask_epi8(hit)) return i + __builtin_ctz(bits);
  }
#endif
  for (; i < t.size(); ++i) {
    const char x = t[i];
    if (x == a || x == b || x == c || x == d || x == e) return i;
  }
  return i;
}

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
    ++pos;
    while (true) {
      pos = next_of<'"', '\\'>(t, pos);
      if (pos >= t.size()) return false;
      if (t[pos] == '"') {
        ++pos;
        return true;
      }
      pos += 2;  // the escaped character cannot close the string
    }
  }

  /// Moves past one value: a string, an object or array (to its matching
  /// bracket), or a scalar (to the next delimiter).
  bool skip_value() {
    skip_space();
    const char c = peek();
    if (c == '"') return skip_string();
    if (c == '{' || c == '[') {
      int depth = 0;
      while (true) {
        pos = next_of<'"', '{', '}', '[', ']'>(t, pos);
        if (pos >= t.size()) return false;
        const char d = t[pos];
        if (d == '"') {
          if (!skip_string()) return false;
          continue;
        }
        depth += d == '{' || d == '[' ? 1 : -1;
        ++pos;
        if (depth == 0) return true;
      }
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
