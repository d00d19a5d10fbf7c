// Fuzz target: the scene readers (scene JSON, part list, standard input) and
// the threaded split of the parts array.
//
// Oracles beyond "no crash, no exception but SceneError":
//  - parse_scene_json gives the same scene, or the same error message, on one
//    thread and on three, as the reference reading parse_scene_json_whole (the
//    fast path splits the parts array itself and scans vertex lists with its
//    own number reader);
//  - when top_level_array finds the parts and the whole text is valid JSON, its
//    elements are exactly the parts array's elements.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "scene/json_split.h"
#include "scene/scene.h"

namespace {

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_scene: oracle failed: %s\n", what);
    std::abort();
  }
}

// A scene written out in full, every double as hexfloat: equal dumps mean
// equal scenes.
std::string dump(const pd::SceneSpec& s) {
  std::ostringstream o;
  o << std::hexfloat;
  auto vec = [&](const auto& m) {
    for (Eigen::Index k = 0; k < m.size(); ++k) o << m.data()[k] << ',';
    o << ';';
  };
  o << s.path << '|' << s.units.value_or("-") << '|';
  if (s.tolerance) o << *s.tolerance;
  o << '\n';
  for (const auto& p : s.parts) {
    o << p.id << '|' << p.where << '|' << p.mesh.value_or("-") << '|' << p.to_scene_units << '|'
      << int(p.pieces) << '|';
    if (p.vertices) vec(*p.vertices);
    vec(p.transform);
    if (p.motion) {
      vec(p.motion->angular);
      vec(p.motion->about);
      vec(p.motion->velocity);
    }
    o << '\n';
  }
  if (s.pairs)
    for (const auto& [a, b] : *s.pairs) o << a << '&' << b << ',';
  o << '\n';
  const auto& v = s.solver;
  o << (v.method ? int(*v.method) : -1) << '|' << (v.seed ? std::to_string(*v.seed) : "-") << '|'
    << v.tau.value_or(-1) << '|' << v.samples.value_or(-1) << '|' << v.grid.value_or(-1) << '|'
    << v.gs_local.value_or(-1) << '\n';
  if (const auto& c = s.checks.clearance) {
    o << c->min << ':';
    for (const auto& p : c->pairs) o << p.a << '&' << p.b << '=' << p.min << ',';
  }
  o << '\n';
  if (const auto& m = s.checks.motion)
    o << m->grid.t0 << ',' << m->grid.t1 << ',' << m->grid.dt << ',' << m->series;
  return o.str();
}

// The scene's dump, or its error message prefixed with '!'. Any exception but
// SceneError escapes and is a finding.
std::string parse(const std::string& text, int threads) {
  try {
    return dump(pd::parse_scene_json(text, "fuzz.json", "base", std::nullopt, threads));
  } catch (const pd::SceneError& e) {
    return std::string("!") + e.what();
  }
}

std::string parse_whole(const std::string& text) {
  try {
    return dump(pd::parse_scene_json_whole(text, "fuzz.json", "base"));
  } catch (const pd::SceneError& e) {
    return std::string("!") + e.what();
  }
}

void check_split(const std::string& text) {
  const auto span = pd::top_level_array(text, "parts");
  if (!span) return;
  check(span->begin < span->end && span->end <= text.size(), "span inside the text");
  check(text[span->begin] == '[' && text[span->end - 1] == ']', "span is bracketed");
  std::size_t last = span->begin;
  for (const auto& [b, e] : span->elements) {
    check(last < b && b < e && e < span->end, "elements ordered inside the span");
    last = e;
  }
  const auto doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded() || !doc.is_object() || !doc.contains("parts")) return;
  const auto& parts = doc["parts"];
  check(parts.is_array() && parts.size() == span->elements.size(), "same number of parts");
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const auto [b, e] = span->elements[k];
    const auto el = nlohmann::json::parse(text.begin() + b, text.begin() + e, nullptr, false);
    check(!el.is_discarded() && el == parts[k], "element equals the part");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  check_split(text);
  const std::string one = parse(text, 1);
  check(one == parse(text, 3), "one thread and three threads agree");
  check(one == parse_whole(text), "the fast path agrees with the whole-text reading");
  try {
    pd::parse_part_list(text, "fuzz.txt");
  } catch (const pd::SceneError&) {
  }
  try {
    pd::parse_stdin_scene(text, std::string("mm"), 2);
  } catch (const pd::SceneError&) {
  }
  return 0;
}
