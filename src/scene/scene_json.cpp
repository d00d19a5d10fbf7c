#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <Eigen/LU>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "brep/brep_file.h"
#include "parallel_for.h"
#include "scene/json_split.h"
#include "scene/json_strict.h"
#include "scene/scene.h"
#include "scene/split_nodes.h"
#include "scene/units.h"
#include "scene/vertex_scan.h"

namespace pd {

using nlohmann::json;

namespace {

// Every error names the file and the JSON path of the field.
struct Ctx {
  const std::string& file;
  [[noreturn]] void fail(const std::string& at, const std::string& what) const {
    throw SceneError(file + ": " + (at.empty() ? "" : at + ": ") + what);
  }
};

const char* type_name(const json& j) {
  return j.type_name();
}

void only_keys(const Ctx& c, const json& obj, const std::string& at,
               const std::set<std::string>& allowed) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (!allowed.count(it.key())) {
      std::string list;
      for (const auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
      c.fail(at.empty() ? it.key() : at + "." + it.key(), "unknown key (allowed: " + list + ")");
    }
  }
}

double number(const Ctx& c, const json& j, const std::string& at) {
  if (!j.is_number()) c.fail(at, std::string("expected a number, got ") + type_name(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) c.fail(at, "not a finite number");
  return v;
}

std::string string(const Ctx& c, const json& j, const std::string& at) {
  if (!j.is_string()) c.fail(at, std::string("expected a string, got ") + type_name(j));
  return j.get<std::string>();
}

std::string unit(const Ctx& c, const json& j, const std::string& at) {
  const std::string u = string(c, j, at);
  if (!unit_in_mm(u)) c.fail(at, "unknown unit \"" + u + "\" (use " + kUnitNames + ")");
  return u;
}

Mat4 transform(const Ctx& c, const json& j, const std::string& at) {
  std::vector<double> v;
  if (!j.is_array()) c.fail(at, "expected a 4x4 array or a list of 16 numbers");
  if (j.size() == 16) {
    for (size_t k = 0; k < 16; ++k)
      v.push_back(number(c, j[k], at + "[" + std::to_string(k) + "]"));
  } else if (j.size() == 4) {
    for (size_t r = 0; r < 4; ++r) {
      const std::string ar = at + "[" + std::to_string(r) + "]";
      if (!j[r].is_array() || j[r].size() != 4) c.fail(ar, "expected a row of 4 numbers");
      for (size_t k = 0; k < 4; ++k)
        v.push_back(number(c, j[r][k], ar + "[" + std::to_string(k) + "]"));
    }
  } else {
    c.fail(at, "expected a 4x4 array or a list of 16 numbers, got " + std::to_string(j.size()) +
                   " entries");
  }
  Mat4 m;
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) m(r, k) = v[4 * r + k];  // row-major in the file
  if (m(3, 0) != 0 || m(3, 1) != 0 || m(3, 2) != 0 || m(3, 3) != 1)
    c.fail(at, "the last row must be [0, 0, 0, 1] (an affine transform)");
  if (std::abs(m.topLeftCorner<3, 3>().determinant()) < 1e-300)
    c.fail(at, "singular transform (it flattens the part)");
  return m;
}

Points vertex_list(const Ctx& c, const json& j, const std::string& at) {
  if (!j.is_array()) c.fail(at, std::string("expected a list of [x, y, z], got ") + type_name(j));
  if (j.empty()) c.fail(at, "empty vertex list");
  // The hot loop of a large scene: a field's path is spelled only on error.
  auto where = [&](size_t k) { return at + "[" + std::to_string(k) + "]"; };
  Points p(3, j.size());
  for (size_t k = 0; k < j.size(); ++k) {
    const json& v = j[k];
    if (!v.is_array() || v.size() != 3) c.fail(where(k), "expected [x, y, z]");
    for (int d = 0; d < 3; ++d) {
      const json& x = v[d];
      p(d, k) = x.is_number() ? x.get<double>() : NAN;
      if (!std::isfinite(p(d, k))) number(c, x, where(k) + "[" + std::to_string(d) + "]");
    }
  }
  return p;
}

/// A part's `tags` (non-empty strings) and `group` (a `/`-separated path of
/// non-empty names), for rules (scene/rules.h).
void part_labels(const Ctx& c, const json& j, const std::string& at, PartSpec& p) {
  if (j.contains("tags")) {
    const json& t = j["tags"];
    if (!t.is_array()) c.fail(at + ".tags", "expected a list of strings");
    for (size_t k = 0; k < t.size(); ++k) {
      p.tags.push_back(string(c, t[k], at + ".tags[" + std::to_string(k) + "]"));
      if (p.tags.back().empty()) c.fail(at + ".tags[" + std::to_string(k) + "]", "empty tag");
    }
  }
  if (j.contains("group")) {
    p.group = string(c, j["group"], at + ".group");
    const std::string& g = p.group;
    if (g.empty() || g.front() == '/' || g.back() == '/' || g.find("//") != std::string::npos)
      c.fail(at + ".group", "expected a path of non-empty names joined by '/' (\"wing/rib-7\")");
  }
}

double positive(const Ctx& c, const json& j, const std::string& at) {
  const double v = number(c, j, at);
  if (!(v > 0)) c.fail(at, "must be > 0");
  return v;
}

/// `scanned`, when given, is the part's vertex list already read by
/// scan_vertex_array (its "vertices" value in `j` is then a placeholder); when
/// it holds nothing, the caller sets the vertices (or their VertexSummary).
PartSpec part(const Ctx& c, const json& j, const std::string& at, const std::string& base_dir,
              const std::string& scene_units, std::optional<Points>* scanned) {
  if (!j.is_object()) c.fail(at, std::string("expected an object, got ") + type_name(j));
  only_keys(c, j, at,
            {"id", "mesh", "vertices", "units", "transform", "pieces", "motion", "sag", "tags",
             "group", "split", "deflection"});
  PartSpec p;
  p.where = c.file + ": " + at;
  if (!j.contains("id")) c.fail(at, "missing \"id\"");
  p.id = string(c, j["id"], at + ".id");
  if (p.id.empty()) c.fail(at + ".id", "empty id");
  p.where += " (\"" + p.id + "\")";
  const bool has_mesh = j.contains("mesh"), has_vertices = j.contains("vertices");
  if (has_mesh == has_vertices) c.fail(at, "give exactly one of \"mesh\" and \"vertices\"");
  if (has_mesh) {
    const std::filesystem::path m = string(c, j["mesh"], at + ".mesh");
    p.mesh =
        (m.is_absolute() || base_dir.empty() ? m : std::filesystem::path(base_dir) / m).string();
  } else if (scanned) {
    if (*scanned) p.vertices = std::move(*scanned);
  } else {
    p.vertices = vertex_list(c, j["vertices"], at + ".vertices");
  }
  const bool brep = p.mesh && is_brep_path(*p.mesh);
  if (j.contains("units")) p.units_key = unit(c, j["units"], at + ".units");
  if (j.contains("units") && !(brep && format_unit(*p.mesh))) {
    p.to_scene_units = *unit_in_mm(*p.units_key) / *unit_in_mm(scene_units);
  } else if (p.mesh) {
    p.to_scene_units = mesh_to_scene_units(*p.mesh, scene_units);  // glTF: metres
  }
  if (j.contains("transform")) p.transform = transform(c, j["transform"], at + ".transform");
  if (j.contains("sag")) {
    const double v = number(c, j["sag"], at + ".sag");
    if (!(v >= 0)) c.fail(at + ".sag", "must be >= 0");
    p.sag = v * p.to_scene_units;  // the part's units, as its vertices
  }
  part_labels(c, j, at, p);
  if (j.contains("pieces")) {
    const std::string v = string(c, j["pieces"], at + ".pieces");
    const std::optional<Pieces> mode = parse_pieces(v);
    if (!mode)
      c.fail(at + ".pieces",
             "expected one of " + std::string(kPiecesNames) + ", got \"" + v + "\"");
    p.pieces = *mode;
    if ((p.pieces == Pieces::kMeshes || p.pieces == Pieces::kDecompose) && !has_mesh)
      c.fail(at + ".pieces", "\"" + v + "\" needs a mesh file");
  }
  if (j.contains("split")) {
    const std::string v = string(c, j["split"], at + ".split");
    if (v != "nodes") c.fail(at + ".split", "expected \"nodes\", got \"" + v + "\"");
    if (!has_mesh) c.fail(at + ".split", "\"nodes\" needs a mesh file");
    p.split_nodes = true;
  } else if (brep) {  // an assembly file: one part per leaf instance
    p.split_nodes = p.split_auto = true;
  }
  if (j.contains("deflection")) {
    if (!brep) c.fail(at + ".deflection", "applies to B-rep files (.step, .stp, .brep) only");
    p.deflection = positive(c, j["deflection"], at + ".deflection");
  }
  return p;
}

Vec3 vec3(const Ctx& c, const json& j, const std::string& at) {
  if (!j.is_array() || j.size() != 3) c.fail(at, "expected [x, y, z]");
  return {number(c, j[0], at + "[0]"), number(c, j[1], at + "[1]"), number(c, j[2], at + "[2]")};
}

RigidMotion motion(const Ctx& c, const json& j, const std::string& at, double to_scene) {
  if (!j.is_object()) c.fail(at, std::string("expected an object, got ") + type_name(j));
  only_keys(c, j, at, {"angular_velocity", "about", "velocity"});
  RigidMotion m;
  if (j.contains("angular_velocity"))
    m.angular = vec3(c, j["angular_velocity"], at + ".angular_velocity");
  if (j.contains("about")) m.about = to_scene * vec3(c, j["about"], at + ".about");
  if (j.contains("velocity")) m.velocity = to_scene * vec3(c, j["velocity"], at + ".velocity");
  return m;
}

// The step count in double precision: a cast of more than 2^63 steps to an
// integer is undefined (it wrapped below the cap and skipped the check).
void time_grid_limits(const Ctx& c, const TimeGrid& g, const std::string& at) {
  const double span = g.t1 - g.t0;
  if (!std::isfinite(span)) c.fail(at + ".t1", "t1 - t0 is beyond the double range");
  const double steps = g.step_count();
  if (!(steps <= kMaxTimeSteps)) {
    std::ostringstream n;
    n << std::setprecision(3) << steps;
    c.fail(at + ".dt", "gives " + n.str() + " time steps, more than " +
                           std::to_string(kMaxTimeSteps) + ": use a larger dt");
  }
  // Grid times must differ: t + dt == t when dt is below the spacing of
  // doubles at t, and the grid would repeat one time.
  const double t = std::max(std::abs(g.t0), std::abs(g.t1));
  if (steps > 1 && !(t + g.dt > t))
    c.fail(at + ".dt", "below the resolution of double-precision times at |t| = " +
                           (std::ostringstream() << t).str() + ": use a larger dt or shift t0");
}

Checks checks(const Ctx& c, const json& j) {
  if (!j.is_object()) c.fail("checks", std::string("expected an object, got ") + type_name(j));
  only_keys(c, j, "checks", {"clearance", "motion"});
  Checks k;
  if (j.contains("clearance")) {
    const json& cl = j["clearance"];
    const std::string at = "checks.clearance";
    if (!cl.is_object()) c.fail(at, "expected an object");
    only_keys(c, cl, at, {"min", "pairs"});
    if (!cl.contains("min")) c.fail(at, "missing \"min\"");
    ClearanceCheck cc;
    cc.min = positive(c, cl["min"], at + ".min");
    if (cl.contains("pairs")) {
      if (!cl["pairs"].is_array()) c.fail(at + ".pairs", "expected a list");
      for (size_t n = 0; n < cl["pairs"].size(); ++n) {
        const json& e = cl["pairs"][n];
        const std::string ae = at + ".pairs[" + std::to_string(n) + "]";
        if (!e.is_object()) c.fail(ae, "expected {\"pair\": [id, id], \"min\": d}");
        only_keys(c, e, ae, {"pair", "min"});
        if (!e.contains("pair") || !e["pair"].is_array() || e["pair"].size() != 2)
          c.fail(ae + ".pair", "expected [id, id]");
        if (!e.contains("min")) c.fail(ae, "missing \"min\"");
        cc.pairs.push_back({string(c, e["pair"][0], ae + ".pair[0]"),
                            string(c, e["pair"][1], ae + ".pair[1]"),
                            positive(c, e["min"], ae + ".min")});
      }
    }
    k.clearance = cc;
  }
  if (j.contains("motion")) {
    const json& mj = j["motion"];
    const std::string at = "checks.motion";
    if (!mj.is_object()) c.fail(at, "expected an object");
    only_keys(c, mj, at, {"t0", "t1", "dt", "series"});
    MotionCheck m;
    if (mj.contains("t0")) m.grid.t0 = number(c, mj["t0"], at + ".t0");
    if (!mj.contains("t1")) c.fail(at, "missing \"t1\"");
    m.grid.t1 = number(c, mj["t1"], at + ".t1");
    if (m.grid.t1 < m.grid.t0) c.fail(at + ".t1", "must be >= t0");
    if (mj.contains("dt")) m.grid.dt = positive(c, mj["dt"], at + ".dt");
    time_grid_limits(c, m.grid, at);
    if (mj.contains("series")) {
      if (!mj["series"].is_boolean()) c.fail(at + ".series", "expected true or false");
      m.series = mj["series"].get<bool>();
    }
    k.motion = m;
  }
  return k;
}

SolverOverrides solver(const Ctx& c, const json& j) {
  const std::string at = "solver";
  if (!j.is_object()) c.fail(at, std::string("expected an object, got ") + type_name(j));
  only_keys(c, j, at, {"method", "seed", "tau", "samples", "grid", "gs_local"});
  SolverOverrides o;
  if (j.contains("method")) {
    const std::string m = string(c, j["method"], at + ".method");
    o.method = parse_method(m);
    if (!o.method)
      c.fail(at + ".method",
             "unknown method \"" + m + "\" (mlsl, mlsl-paper, gs-local, grid, exact)");
  }
  auto positive_int = [&](const char* key, int max) -> std::optional<int> {
    if (!j.contains(key)) return std::nullopt;
    const std::string ak = at + "." + key;
    if (!j[key].is_number_integer() || j[key].get<long long>() < 1 || j[key].get<long long>() > max)
      c.fail(ak, "expected an integer from 1 to " + std::to_string(max));
    return j[key].get<int>();
  };
  if (j.contains("seed")) {
    if (!j["seed"].is_number_unsigned()) c.fail(at + ".seed", "expected a non-negative integer");
    o.seed = j["seed"].get<std::uint64_t>();
  }
  if (j.contains("tau")) {
    o.tau = number(c, j["tau"], at + ".tau");
    if (!(*o.tau > 0 && *o.tau < 1)) c.fail(at + ".tau", "expected 0 < tau < 1");
  }
  o.samples = positive_int("samples", 100000);
  o.grid = positive_int("grid", kMaxGrid);
  o.gs_local = positive_int("gs_local", kMaxGsLocal);
  return o;
}

std::string line_column(std::string_view text, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t k = 0; k + 1 < byte && k < text.size(); ++k) {
    if (text[k] == '\n')
      ++line, col = 1;
    else
      ++col;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

}  // namespace

void SolverOverrides::apply(SolverSettings& s) const {
  if (method) s.method = *method;
  if (seed) s.seed = *seed;
  if (tau) s.tau = *tau;
  if (samples) s.samples = *samples;
  if (grid) s.grid = *grid;
  if (gs_local) s.gs_local = *gs_local;
}

namespace {

json parse_json(std::string_view text, const std::string& path) {
  try {
    return parse_json_strict(text.data(), text.data() + text.size());
  } catch (const JsonTextError& e) {
    std::string msg = e.what();
    const auto pos = msg.find("error while parsing");
    throw SceneError(path + ": " + (e.byte ? "invalid JSON at " + line_column(text, e.byte) : "") +
                     (e.byte && !e.path.empty() ? ": " : "") + e.path + ": " +
                     (pos == std::string::npos ? msg : msg.substr(pos)));
  }
}

/// "tolerance": a number > 0, "auto", or {"auto": true, "min": …, "max": …}.
void tolerance(const Ctx& c, const json& j, SceneSpec& s) {
  if (j.is_string()) {
    if (j.get<std::string>() != "auto")
      c.fail("tolerance", "expected a number > 0, \"auto\" or {\"auto\": true, ...}, got \"" +
                              j.get<std::string>() + "\"");
    s.auto_tolerance = AutoTolerance{};
    s.tolerance = 0.0;
    return;
  }
  if (j.is_object()) {
    only_keys(c, j, "tolerance", {"auto", "min", "max"});
    if (!j.contains("auto") || !j["auto"].is_boolean() || !j["auto"].get<bool>())
      c.fail("tolerance.auto", "expected true");
    AutoTolerance a;
    if (j.contains("min")) {
      a.min = number(c, j["min"], "tolerance.min");
      if (!(*a.min > 0)) c.fail("tolerance.min", "must be > 0");
    }
    if (j.contains("max")) {
      a.max = number(c, j["max"], "tolerance.max");
      if (!(*a.max > 0)) c.fail("tolerance.max", "must be > 0");
      if (a.min && *a.max < *a.min) c.fail("tolerance.max", "must be >= tolerance.min");
    }
    s.auto_tolerance = a;
    s.tolerance = a.min.value_or(0.0);
    return;
  }
  s.tolerance = number(c, j, "tolerance");
  if (!(*s.tolerance > 0)) c.fail("tolerance", "must be > 0");
}

/// Everything but the parts (they are converted by `scene_part`): the fields a
/// part's conversion needs (units, checks.motion) are read first.
SceneSpec scene_fields(const Ctx& c, const json& doc, const std::optional<std::string>& units) {
  if (!doc.is_object()) c.fail("", "a scene is a JSON object");
  only_keys(c, doc, "",
            {"$schema", "version", "units", "tolerance", "parts", "pairs", "solver", "checks",
             "rules", "deflection"});
  SceneSpec s;
  s.path = c.file;
  if (doc.contains("version") && (!doc["version"].is_number_integer() || doc["version"] != 1))
    c.fail("version", "only version 1 is known");
  if (doc.contains("units")) s.units = unit(c, doc["units"], "units");
  // A declared unit is never reinterpreted: reading a mm scene's translations and
  // tolerance as inches while its parts that declare mm stay mm moves them apart.
  if (units && s.units && *units != *s.units)
    c.fail("units", "the scene declares \"" + *s.units + "\" but --units says \"" + *units +
                        "\": a declared unit is never reinterpreted (drop --units, or change the "
                        "scene's \"units\")");
  if (units) s.units = units;
  if (doc.contains("tolerance")) tolerance(c, doc["tolerance"], s);
  if (doc.contains("deflection")) s.deflection = positive(c, doc["deflection"], "deflection");
  if (!doc.contains("parts")) c.fail("", "missing \"parts\"");
  const json& parts = doc["parts"];
  if (!parts.is_array()) c.fail("parts", std::string("expected a list, got ") + type_name(parts));
  if (doc.contains("pairs")) {
    const json& pj = doc["pairs"];
    if (!pj.is_array()) c.fail("pairs", "expected a list of [id, id]");
    s.pairs.emplace();
    for (size_t k = 0; k < pj.size(); ++k) {
      const std::string at = "pairs[" + std::to_string(k) + "]";
      if (!pj[k].is_array() || pj[k].size() != 2) c.fail(at, "expected [id, id]");
      s.pairs->emplace_back(string(c, pj[k][0], at + "[0]"), string(c, pj[k][1], at + "[1]"));
    }
  }
  if (doc.contains("solver")) s.solver = solver(c, doc["solver"]);
  if (doc.contains("checks")) s.checks = checks(c, doc["checks"]);
  if (doc.contains("rules"))
    attach_rules(s, parse_rules(doc["rules"], c.file, "rules", s.units.value_or("mm")));
  return s;
}

/// Part k of the scene, its motion included.
PartSpec scene_part(const Ctx& c, const json& j, size_t k, const std::string& base_dir,
                    const SceneSpec& s, std::optional<Points>* scanned = nullptr) {
  const std::string at = "parts[" + std::to_string(k) + "]";
  PartSpec p = part(c, j, at, base_dir, s.units.value_or("mm"), scanned);
  if (j.contains("motion")) {
    if (!s.checks.motion)
      c.fail(at + ".motion", "a motion needs a time grid: add checks.motion {t0, t1, dt}");
    p.motion = motion(c, j["motion"], at + ".motion", 1.0);  // scene units
  }
  return p;
}

/// Part element [b, e) of the text, `offset` bytes into the file. Its inline
/// vertex list, when plain, is read by scan_vertex_array and the rest of the
/// element by the general parser with `null` in its place (the general parse
/// of 3 numbers per vertex was most of a large scene's load:
/// docs/performance.md). Without `keep_vertices`, the list of a part that does
/// not move is scanned into a reused buffer and only its VertexSummary kept.
PartSpec parse_part_element(const Ctx& c, const char* b, const char* e, size_t k,
                            const std::string& base_dir, const SceneSpec& s, size_t offset,
                            bool keep_vertices) {
  const std::string_view element(b, static_cast<size_t>(e - b));
  thread_local std::vector<double> xyz;
  const auto span = read_top_level_array(element, "vertices", [](std::string_view from) {
    return scan_vertex_prefix(from, xyz);  // the key found and the list read in one pass
  });
  if (span) {
    const std::string_view list = element.substr(span->begin, span->end - span->begin);
    {
      std::string rest;
      rest.reserve(element.size() - list.size() + 4);
      rest.append(element.substr(0, span->begin)).append("null").append(element.substr(span->end));
      std::optional<Points> none;
      PartSpec p = scene_part(c, parse_json_strict(rest), k, base_dir, s, &none);
      const Eigen::Map<const Points> list_xyz(xyz.data(), 3,
                                              static_cast<Eigen::Index>(xyz.size() / 3));
      if (keep_vertices || p.motion) {
        p.vertices = Points(list_xyz);
      } else {
        const Points v = list_xyz;  // freed at once: its memory is reused by the next part
        VertexSummary sum;
        sum.count = v.cols();
        const Points placed = place_points(v, p);
        if (placed.allFinite()) sum.placed_box = Aabb::of(placed);
        const std::string digest = vertex_digest(v);
        std::copy(digest.begin(), digest.end(), sum.digest.begin());
        sum.offset = offset + span->begin;
        sum.length = list.size();
        p.vertex_summary = std::move(sum);
      }
      return p;
    }
  }
  return scene_part(c, parse_json_strict(b, e), k, base_dir, s);
}

/// The parts array split at its elements, each parsed and converted on its own
/// thread. std::nullopt on anything unexpected: the whole-text parse then runs
/// and reports the error with the right line and column.
std::optional<SceneSpec> parse_in_slices(std::string_view text, const Ctx& c,
                                         const std::string& base_dir,
                                         const std::optional<std::string>& units, int threads,
                                         bool keep_vertices) {
  const auto span = top_level_array(text, "parts");
  if (!span || span->elements.size() < 2) return std::nullopt;
  try {
    std::string rest(text.substr(0, span->begin));
    rest.append("[]").append(text.substr(span->end));
    const json doc = parse_json_strict(rest);
    SceneSpec s = scene_fields(c, doc, units);
    s.parts.resize(span->elements.size());
    parallel_for(s.parts.size(), threads, [&](size_t k) {
      const auto [b, e] = span->elements[k];
      s.parts[k] =
          parse_part_element(c, text.data() + b, text.data() + e, k, base_dir, s, b, keep_vertices);
    });
    return s;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

namespace {

SceneSpec parse_scene_text(std::string_view text, const std::string& path,
                           const std::string& base_dir, const std::optional<std::string>& units,
                           int threads, bool keep_vertices) {
  std::optional<SceneSpec> s =
      parse_in_slices(text, Ctx{path}, base_dir, units, threads, keep_vertices);
  if (!s) return parse_scene_json_whole(text, path, base_dir, units);
  validate_scene(*s);
  return std::move(*s);
}

}  // namespace

SceneSpec parse_scene_json(std::string_view text, const std::string& path,
                           const std::string& base_dir, const std::optional<std::string>& units,
                           int threads) {
  return parse_scene_text(text, path, base_dir, units, threads, true);
}

SceneSpec parse_scene_json_whole(std::string_view text, const std::string& path,
                                 const std::string& base_dir,
                                 const std::optional<std::string>& units) {
  const Ctx c{path};
  const json doc = parse_json(text, path);
  SceneSpec s = scene_fields(c, doc, units);
  const json& parts = doc["parts"];
  for (size_t k = 0; k < parts.size(); ++k)
    s.parts.push_back(scene_part(c, parts[k], k, base_dir, s));
  validate_scene(s);
  return s;
}

namespace {

/// The whole file. A regular file is read with read(2) straight into a buffer
/// of its size (scenes reach 100 MB: a read into a string first zero-fills its
/// pages and then copies, which was a third of a large scene's load). Not
/// mapped: a file cut short while mapped (an exporter rewriting it in place)
/// kills the reader with SIGBUS, where a read just sees a shorter file, whose
/// JSON error names it. Anything else (a FIFO such as `<(generate-scene)`) is
/// read as a stream.
class SceneText {
 public:
  explicit SceneText(const std::string& path) {
    std::error_code ec;
    const auto st = std::filesystem::status(path, ec);
    if (std::filesystem::is_directory(st))
      throw SceneError(path + ": is a directory, not a scene file");
    if (std::filesystem::is_regular_file(st) && read_whole(path)) return;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open the scene file");
    read_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad()) throw SceneError(path + ": cannot read the scene file");
    view_ = read_;
  }
  ~SceneText() {
    if (buffer_) munmap(buffer_, capacity_);
  }
  SceneText(const SceneText&) = delete;
  SceneText& operator=(const SceneText&) = delete;
  std::string_view text() const { return view_; }
  /// Read whole from a regular file: its bytes can be read again by offset.
  bool rereadable() const { return buffer_ != nullptr; }

 private:
  /// False (the stream reads it instead) when the file cannot be opened or read this way.
  bool read_whole(const std::string& path) {
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    struct stat st;
    bool ok = fstat(fd, &st) == 0 && st.st_size > 0;
    size_t got = 0;
    if (ok) {
      const size_t size = static_cast<size_t>(st.st_size);
      // Anonymous memory populated in one call: page by page, the faults on a
      // 50 MB buffer cost about as much as the read itself.
      void* p = mmap(nullptr, size, PROT_READ | PROT_WRITE,
                     MAP_PRIVATE | MAP_ANONYMOUS | MAP_POPULATE, -1, 0);
      if (p == MAP_FAILED) {
        close(fd);
        return false;
      }
      buffer_ = static_cast<char*>(p);
      capacity_ = size;
      while (got < size) {
        const ssize_t n = ::read(fd, buffer_ + got, size - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
          ok = n == 0;  // end of file: the file shrank, read what is there
          break;
        }
        got += static_cast<size_t>(n);
      }
    }
    close(fd);
    if (!ok) return false;
    view_ = std::string_view(buffer_, got);
    return true;
  }
  char* buffer_ = nullptr;
  size_t capacity_ = 0;
  std::string read_;
  std::string_view view_;
};

}  // namespace

SceneSpec load_scene_file(const std::string& path, const std::optional<std::string>& units,
                          int threads, bool keep_vertices) {
  const SceneText file(path);
  const std::string base = std::filesystem::path(path).parent_path().string();
  try {
    return parse_scene_text(file.text(), path, base, units, threads,
                            keep_vertices || !file.rereadable());
  } catch (const SceneError& e) {
    // `pdcheck part.stl`: say what was meant, not only that it is no JSON.
    if (looks_like_mesh_file(path))
      throw SceneError(std::string(e.what()) + "; " + path +
                       " looks like a mesh file, not a scene: to check mesh files, list them on "
                       "standard input (ls " +
                       path + " other.stl | pdcheck - --tolerance 0.05)");
    throw;
  }
}

void attach_rules(SceneSpec& s, Rules rules) {
  double reach = 0.0;
  std::string first;
  for (const RuleTest& t : rules.tests)
    if (t.clearance) {
      reach = std::max(reach, *t.clearance);
      if (first.empty()) first = t.where;
    }
  for (const PairRule& p : rules.pairs)
    if (p.clearance) {
      reach = std::max(reach, *p.clearance);
      if (first.empty()) first = p.where;
    }
  if (reach > 0 && !s.checks.clearance)
    throw SceneError(first +
                     ": clearance: a rule's clearance refines the scene's clearance check: add "
                     "\"checks\": {\"clearance\": {\"min\": ...}} to the scene");
  if (s.checks.clearance) s.checks.clearance->rules_reach = reach;
  s.rules = std::move(rules);
}

void validate_scene(const SceneSpec& s) {
  std::set<std::string> ids;
  for (size_t k = 0; k < s.parts.size(); ++k) {
    if (!ids.insert(s.parts[k].id).second)
      throw SceneError(s.parts[k].where + ": duplicate part id \"" + s.parts[k].id + "\"");
  }
  if (s.pairs) {
    for (size_t k = 0; k < s.pairs->size(); ++k) {
      const auto& [a, b] = (*s.pairs)[k];
      for (const auto& id : {a, b})
        if (!ids.count(id) && !under_unsplit_part(s, id))
          throw SceneError(s.path + ": pairs[" + std::to_string(k) + "]: unknown part id \"" + id +
                           "\"");
      if (a == b)
        throw SceneError(s.path + ": pairs[" + std::to_string(k) + "]: a part paired with itself");
    }
  }
  if (s.checks.clearance) {
    for (size_t k = 0; k < s.checks.clearance->pairs.size(); ++k)
      for (const auto& id : {s.checks.clearance->pairs[k].a, s.checks.clearance->pairs[k].b})
        if (!ids.count(id) && !under_unsplit_part(s, id))
          throw SceneError(s.path + ": checks.clearance.pairs[" + std::to_string(k) +
                           "]: unknown part id \"" + id + "\"");
  }
}

}  // namespace pd
