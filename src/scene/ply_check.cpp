#include "scene/ply_check.h"

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <sstream>
#include <vector>

#include "scene/mesh_loader.h"
#include "tolerances.h"

// Two behaviours of Debian's assimp 5.2.5 PLY reader are worked around here,
// by handing it an equivalent file from memory (remove when assimp is fixed):
//
// 1. Binary data whose first byte is 0x0a ('\n') is read one byte late: the
//    reader takes that byte as part of the `end_header` line's end, so every
//    value after it is shifted (NaN errors, or silently wrong geometry; about
//    1 binary PLY in 256, by the value of its first byte alone). The rewrite
//    declares a one-instance element of one uchar before the others, whose
//    data byte is 'A': the data then starts with 'A' and the real data
//    follows byte for byte, whatever the endianness, types and properties.
//    The element is named `edge`, a name the reader knows and skips (see 2).
// 2. An element whose name the reader does not know (anything but vertex,
//    face, tristrips, edge, material) is taken to have 0 instances, so a
//    custom element before `vertex` shifts the data of every later element.
//    The rewrite leaves out every element but vertex, face and tristrips
//    (the only ones that carry geometry), data included.
//
// 3. A header line it does not know is skipped (not an error), but one among
//    an element's properties ends that element's property list there. Such a
//    line before the first element (free text, as Blender 2.4 wrote) is left
//    out of the rewrite with a warning; after it, it is refused.
//
// Whatever assimp returns is then compared with the vertices read here
// (check_ply_read), so a misreading not worked around is an error, not
// wrong geometry.

namespace pd {

namespace {

enum class Kind { kSigned, kUnsigned, kFloat };

struct Type {
  int size = 0;  // bytes; 0 = unknown
  Kind kind = Kind::kSigned;
};

Type type_of(std::string_view name) {
  static const struct {
    const char* name;
    Type type;
  } kTypes[] = {{"char", {1, Kind::kSigned}},     {"int8", {1, Kind::kSigned}},
                {"uchar", {1, Kind::kUnsigned}},  {"uint8", {1, Kind::kUnsigned}},
                {"short", {2, Kind::kSigned}},    {"int16", {2, Kind::kSigned}},
                {"ushort", {2, Kind::kUnsigned}}, {"uint16", {2, Kind::kUnsigned}},
                {"int", {4, Kind::kSigned}},      {"int32", {4, Kind::kSigned}},
                {"uint", {4, Kind::kUnsigned}},   {"uint32", {4, Kind::kUnsigned}},
                {"float", {4, Kind::kFloat}},     {"float32", {4, Kind::kFloat}},
                {"double", {8, Kind::kFloat}},    {"float64", {8, Kind::kFloat}}};
  for (const auto& t : kTypes)
    if (name == t.name) return t.type;
  return {};
}

struct Property {
  std::string name;
  Type type;   // of the value, or of the list items
  Type count;  // of the list length; size 0 = not a list
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  std::vector<std::string> lines;  // its header lines, for a rewrite
  size_t begin = 0, end = 0;       // its data in the file
};

enum class Format { kAscii, kLittle, kBig };

/// Printable, bounded: a token of a damaged file may be anything.
std::string ply_quoted(std::string_view s) {
  std::string out = "\"";
  for (size_t k = 0; k < s.size() && k < 40; ++k) {
    const unsigned char c = s[k];
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
      out += char(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  return out + (s.size() > 40 ? "…\"" : "\"");
}

[[noreturn]] void fail(const std::string& why) {
  throw MeshError("PLY " + why);
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) ++k;
    const size_t b = k;
    while (k < line.size() && line[k] != ' ' && line[k] != '\t') ++k;
    if (k > b) out.push_back(line.substr(b, k - b));
  }
  return out;
}

/// Offset of the data: just past the first `end_header` line.
size_t header_end(std::string_view bytes) {
  size_t at = 0;
  while ((at = bytes.find("\nend_header", at)) != std::string_view::npos) {
    size_t k = at + 11;
    while (k < bytes.size() && (bytes[k] == ' ' || bytes[k] == '\t' || bytes[k] == '\r')) ++k;
    if (k == bytes.size()) return k;
    if (bytes[k] == '\n') return k + 1;
    at = k;
  }
  fail("header has no end_header line (the file is cut inside its header, or is not PLY)");
}

double decode(const unsigned char* p, Type t, bool swap) {
  unsigned char b[8];
  std::memcpy(b, p, t.size);
  if (swap) std::reverse(b, b + t.size);
  switch (t.size * 4 + int(t.kind)) {
#define PD_CASE(SIZE, KIND, CTYPE) \
  case SIZE * 4 + int(KIND): {     \
    CTYPE v;                       \
    std::memcpy(&v, b, SIZE);      \
    return double(v);              \
  }
    PD_CASE(1, Kind::kSigned, std::int8_t)
    PD_CASE(1, Kind::kUnsigned, std::uint8_t)
    PD_CASE(2, Kind::kSigned, std::int16_t)
    PD_CASE(2, Kind::kUnsigned, std::uint16_t)
    PD_CASE(4, Kind::kSigned, std::int32_t)
    PD_CASE(4, Kind::kUnsigned, std::uint32_t)
    PD_CASE(4, Kind::kFloat, float)
    PD_CASE(8, Kind::kFloat, double)
#undef PD_CASE
  }
  return 0.0;
}

bool host_is_big_endian() {
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

std::string where(const Element& e, std::uint64_t instance) {
  return "element " + ply_quoted(e.name) + " instance " + std::to_string(instance) + " of " +
         std::to_string(e.count);
}

/// Walks binary data from `pos`; fills each element's range and the vertices.
void walk_binary(std::string_view bytes, size_t pos, bool big, std::vector<Element>& elements,
                 const int xyz[3], size_t vertex_element, Points& vertices) {
  const bool swap = big != host_is_big_endian();
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  for (size_t e = 0; e < elements.size(); ++e) {
    Element& el = elements[e];
    el.begin = pos;
    bool fixed = true;
    size_t record = 0;
    for (const Property& p : el.properties) {
      fixed = fixed && p.count.size == 0;
      record += p.count.size ? 0 : p.type.size;
    }
    if (fixed && e != vertex_element) {  // no need to visit each instance
      if (record > 0 && (bytes.size() - pos) / record < el.count)
        fail("data cut short: " + where(el, (bytes.size() - pos) / record) + " is past the end");
      pos += record * el.count;
      el.end = pos;
      continue;
    }
    for (std::uint64_t i = 0; i < el.count; ++i) {
      for (size_t k = 0; k < el.properties.size(); ++k) {
        const Property& p = el.properties[k];
        std::uint64_t items = 1;
        if (p.count.size) {
          if (bytes.size() - pos < size_t(p.count.size))
            fail("data cut short: " + where(el, i) + " is past the end");
          const double n = decode(data + pos, p.count, swap);
          if (n < 0)
            fail(where(el, i) + ": list " + ply_quoted(p.name) + " has negative length " +
                 std::to_string(long(n)));
          items = std::uint64_t(n);
          pos += p.count.size;
        }
        if ((bytes.size() - pos) / p.type.size < items)
          fail("data cut short: " + where(el, i) + " is past the end");
        if (e == vertex_element)
          for (int c = 0; c < 3; ++c)
            if (int(k) == xyz[c]) vertices(c, i) = decode(data + pos, p.type, swap);
        pos += items * p.type.size;
      }
    }
    el.end = pos;
  }
}

/// No control characters but tabs: a line of text, not damaged bytes.
bool text_line(std::string_view line) {
  return std::none_of(line.begin(), line.end(), [](char c) {
    return (static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f;
  });
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

/// Walks ASCII data from `pos`: one token per value, a length token per list.
void walk_ascii(std::string_view bytes, size_t pos, std::vector<Element>& elements,
                const int xyz[3], size_t vertex_element, Points& vertices) {
  auto token = [&](const Element& el, std::uint64_t i) {
    while (pos < bytes.size() && is_space(bytes[pos])) ++pos;
    const size_t b = pos;
    while (pos < bytes.size() && !is_space(bytes[pos])) ++pos;
    if (pos == b) fail("data cut short: " + where(el, i) + " is past the end");
    return bytes.substr(b, pos - b);
  };
  auto number = [&](std::string_view t, const Element& el, std::uint64_t i) {
    double v = 0;
    const char* first = t.data() + (t.size() > 1 && t[0] == '+' ? 1 : 0);
    const auto r = std::from_chars(first, t.data() + t.size(), v);
    if (r.ec == std::errc::result_out_of_range)
      fail(where(el, i) + ": " + ply_quoted(t) + " is out of the range of a double");
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(where(el, i) + ": " + ply_quoted(t) + " is not a number");
    return v;
  };
  for (size_t e = 0; e < elements.size(); ++e) {
    Element& el = elements[e];
    while (pos < bytes.size() && is_space(bytes[pos])) ++pos;
    el.begin = el.end = pos;
    for (std::uint64_t i = 0; i < el.count && !el.properties.empty(); ++i) {
      for (size_t k = 0; k < el.properties.size(); ++k) {
        const Property& p = el.properties[k];
        std::uint64_t items = 1;
        if (p.count.size) {
          const double n = number(token(el, i), el, i);
          if (!(n >= 0 && n <= 1e15) || n != std::floor(n))
            fail(where(el, i) + ": list " + ply_quoted(p.name) + " has length " +
                 std::to_string(n) + ", not a whole number >= 0");
          items = std::uint64_t(n);
        }
        for (std::uint64_t j = 0; j < items; ++j) {
          const double v = number(token(el, i), el, i);
          if (e == vertex_element)
            for (int c = 0; c < 3; ++c)
              if (int(k) == xyz[c]) vertices(c, i) = v;
        }
      }
      el.end = pos;
    }
  }
}

// What the header says, and what the rewrite for assimp needs of it.
struct Header {
  std::vector<Element> elements;
  std::optional<Format> format;
  std::string format_line;
  bool skipped = false;  // an unknown header line: assimp gets the header without it
};

Format format_of(const std::vector<std::string_view>& w, const std::string& at) {
  if (w.size() != 3) fail(at + "expected \"format <ascii|binary_…> 1.0\"");
  if (w[1] == "ascii") return Format::kAscii;
  if (w[1] == "binary_little_endian") return Format::kLittle;
  if (w[1] == "binary_big_endian") return Format::kBig;
  fail(at + "unknown format " + ply_quoted(w[1]));
}

Element element_of(const std::vector<std::string_view>& w, std::string_view line,
                   const std::string& at) {
  std::uint64_t n = 0;
  if (w.size() != 3 ||
      std::from_chars(w[2].data(), w[2].data() + w[2].size(), n).ptr != w[2].data() + w[2].size())
    fail(at + "expected \"element <name> <count>\"");
  if (n > std::uint64_t(INT32_MAX))
    fail(at + "element count " + ply_quoted(w[2]) + " is too large");
  return {std::string(w[1]), n, {}, {std::string(line)}, 0, 0};
}

Property property_of(const std::vector<std::string_view>& w, const std::string& at) {
  Property p;
  if (w.size() == 5 && w[1] == "list") {
    p.count = type_of(w[2]);
    p.type = type_of(w[3]);
    p.name = w[4];
    if (!p.count.size) fail(at + "unknown property type " + ply_quoted(w[2]));
    if (p.count.kind == Kind::kFloat)
      fail(at + "a list length must have an integer type, not " + ply_quoted(w[2]));
    if (!p.type.size) fail(at + "unknown property type " + ply_quoted(w[3]));
  } else if (w.size() == 3) {
    p.type = type_of(w[1]);
    p.name = w[2];
    if (!p.type.size) fail(at + "unknown property type " + ply_quoted(w[1]));
  } else {
    fail(at + "expected \"property <type> <name>\" or \"property list <type> <type> <name>\"");
  }
  return p;
}

// assimp skips a header line it does not know (Blender 2.4's exporter wrote
// "Created by Blender3D 247 - …" without `comment`); so does this check, with
// a warning. The line is left out of what assimp gets: among an element's
// properties it would end assimp's property list there.
void skip_unknown_line(const std::vector<std::string_view>& w, std::string_view line,
                       const std::string& at, Header& h, std::vector<std::string>& warnings) {
  if (!text_line(line)) fail(at + "unknown line " + ply_quoted(line) + " is not text");
  // Only before the first element, where exporters put their free text.
  // Among elements the rewrite would hand assimp a header it was never
  // fuzzed on, and fuzzing found assimp 5.2.5 corrupting its heap on
  // such rewritten headers (duplicate elements after the skipped line).
  if (!h.elements.empty())
    fail(at + "unknown keyword " + ply_quoted(w[0]) +
         " after the first element (only before it is a free-text line skipped)");
  warnings.push_back("PLY " + at + "unknown line " + ply_quoted(line) +
                     " skipped (neither comment, element nor property)");
  h.skipped = true;
}

/// The header's lines from the second (after "ply") up to `data`, each
/// checked as it comes, so an error names the first bad line.
Header parse_header(std::string_view bytes, size_t data, std::vector<std::string>& warnings) {
  Header h;
  size_t pos = bytes.find('\n') + 1;
  for (int line_no = 2; pos < data; ++line_no) {
    size_t eol = bytes.find('\n', pos);
    if (eol == std::string_view::npos || eol > data) eol = data;
    std::string_view line = bytes.substr(pos, eol - pos);
    pos = eol + 1;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
    const auto w = words(line);
    const std::string at = "header line " + std::to_string(line_no) + ": ";
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (h.format) fail(at + "a second format line (a PLY file has one)");
      h.format = format_of(w, at);
      h.format_line = std::string(line);
    } else if (w[0] == "element") {
      Element e = element_of(w, line, at);
      // assimp 5.2.5 sizes a geometry element's buffers by its first
      // declaration and writes the second's instances past them (a heap
      // overrun fuzzing found); no exporter writes one twice.
      if (e.name == "vertex" || e.name == "face" || e.name == "tristrips")
        for (const Element& before : h.elements)
          if (before.name == e.name)
            fail(at + "a second element " + ply_quoted(e.name) + " (a PLY file declares it once)");
      h.elements.push_back(std::move(e));
    } else if (w[0] == "property") {
      if (h.elements.empty()) fail(at + "property before any element");
      h.elements.back().properties.push_back(property_of(w, at));
      h.elements.back().lines.emplace_back(line);
    } else {
      skip_unknown_line(w, line, at, h, warnings);
    }
  }
  if (!h.format) fail("header has no format line");
  return h;
}

// Counts bounded by the data before anything is sized by them: an instance
// takes at least its fixed bytes (binary) or a digit and a separator per
// value (ASCII), so a damaged count cannot ask for gigabytes.
void check_counts(const Header& h, size_t data_bytes) {
  for (const Element& e : h.elements) {
    size_t least = 0;
    for (const Property& p : e.properties)
      least += *h.format == Format::kAscii ? 2 : (p.count.size ? p.count.size : p.type.size);
    if (least > 0 && e.count > data_bytes / least)
      fail("data cut short: element " + ply_quoted(e.name) + " declares " +
           std::to_string(e.count) + " instances, the data holds at most " +
           std::to_string(data_bytes / least));
  }
}

/// The first element named "vertex" (elements.size() if none), with the
/// indices of its x, y, z properties in `xyz`; sizes `vertices` for it.
size_t vertex_element_of(const std::vector<Element>& elements, int xyz[3], Points& vertices) {
  size_t vertex_element = elements.size();
  for (size_t e = 0; e < elements.size() && vertex_element == elements.size(); ++e)
    if (elements[e].name == "vertex") vertex_element = e;
  if (vertex_element < elements.size()) {
    const Element& v = elements[vertex_element];
    for (size_t k = 0; k < v.properties.size(); ++k)
      for (int c = 0; c < 3; ++c)
        if (v.properties[k].name == std::string(1, char('x' + c)) && !v.properties[k].count.size)
          xyz[c] = int(k);
    for (int c = 0; c < 3; ++c)
      if (xyz[c] < 0) fail("element \"vertex\" has no property " + std::string(1, char('x' + c)));
    vertices.setZero(3, Eigen::Index(v.count));
  }
  return vertex_element;
}

// The file assimp gets: only the elements with geometry, and a pad element
// when binary data would start with 0x0a (see the top of this file). Sets
// out.for_assimp, and out.rewritten when it differs from `bytes`.
void prepare_for_assimp(std::string_view bytes, const Header& header, PlyFile& out) {
  std::vector<const Element*> kept;
  for (const Element& e : header.elements)
    if (e.name == "vertex" || e.name == "face" || e.name == "tristrips") kept.push_back(&e);
  const char* first = nullptr;
  for (const Element* e : kept)
    if (e->end > e->begin) {
      first = bytes.data() + e->begin;
      break;
    }
  const bool pad = !out.ascii && first && *first == '\n';
  if (kept.size() == header.elements.size() && !pad && !header.skipped) {
    out.for_assimp = std::string(bytes);
    return;
  }
  std::string h = "ply\n" + header.format_line + "\n";
  if (pad) h += "element edge 1\nproperty uchar pdcheck_pad\n";
  for (const Element* e : kept)
    for (const auto& l : e->lines) h += l + "\n";
  h += "end_header\n";
  if (pad) h += 'A';
  for (const Element* e : kept) {
    h.append(bytes.data() + e->begin, e->end - e->begin);
    if (out.ascii) h += '\n';
  }
  out.for_assimp = std::move(h);
  out.rewritten = true;
}

}  // namespace

bool looks_like_ply(std::string_view bytes) {
  return bytes.size() >= 4 && bytes.substr(0, 3) == "ply" && (bytes[3] == '\n' || bytes[3] == '\r');
}

PlyFile check_ply(std::string_view bytes) {
  if (!looks_like_ply(bytes)) fail("file does not start with the line \"ply\"");
  const size_t data = header_end(bytes);
  PlyFile out;
  Header header = parse_header(bytes, data, out.warnings);
  check_counts(header, bytes.size() - data);
  int xyz[3] = {-1, -1, -1};
  const size_t vertex_element = vertex_element_of(header.elements, xyz, out.vertices);
  out.ascii = *header.format == Format::kAscii;
  if (out.ascii)
    walk_ascii(bytes, data, header.elements, xyz, vertex_element, out.vertices);
  else
    walk_binary(bytes, data, *header.format == Format::kBig, header.elements, xyz, vertex_element,
                out.vertices);
  prepare_for_assimp(bytes, header, out);
  return out;
}

void check_ply_read(const PlyFile& file, const Eigen::Matrix<float, 3, Eigen::Dynamic>& read) {
  const Points& v = file.vertices;
  for (Eigen::Index i = 0; i < v.cols(); ++i)
    for (int c = 0; c < 3; ++c)
      if (std::isfinite(v(c, i)) && std::abs(v(c, i)) > double(FLT_MAX)) {
        std::ostringstream m;
        m.precision(17);
        m << "PLY vertex " << i << ": coordinate " << v(c, i)
          << " is beyond the single precision (about 3.4e38) the mesh loader stores";
        throw MeshError(m.str());
      }
  auto same = [&](double in_file, float got) {
    if (std::isnan(in_file)) return std::isnan(got);
    const float want = float(in_file);
    if (!file.ascii) return want == got;
    // assimp parses ASCII numbers with its own fast_atof, not correctly
    // rounded: a misreading is off by far more than a few units in the last place.
    return std::abs(double(want) - double(got)) <=
           tol::kPlyAsciiAgreement * std::abs(double(want)) + 1e-30;
  };
  std::ostringstream m;
  m.precision(9);
  if (read.cols() == v.cols()) {
    for (Eigen::Index i = 0; i < v.cols(); ++i)
      for (int c = 0; c < 3; ++c)
        if (!same(v(c, i), read(c, i))) {
          m << "the mesh loader misread the file (PLY): vertex " << i << " is (" << v(0, i) << ", "
            << v(1, i) << ", " << v(2, i) << ") in the file but was read as (" << read(0, i) << ", "
            << read(1, i) << ", " << read(2, i) << ")";
          throw MeshError(m.str());
        }
    return;
  }
  // The loader made its own vertex list (counts differ): only non-finite
  // values where the file has none can be told apart from the file's own.
  if (v.allFinite() && !read.allFinite())
    throw MeshError(
        "the mesh loader misread the file (PLY): it returned non-finite coordinates where "
        "the file holds finite ones");
}

}  // namespace pd
