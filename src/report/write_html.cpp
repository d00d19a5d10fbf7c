// The HTML page: the report's findings as JSON data and their geometry as
// base64 typed arrays in one <script type="application/json">, the page's own
// script and style (src/report/html/, embedded at build time) and three.js
// (read from the installed package at generation time) inlined.
#include "report/write_html.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "report/finding_text.h"
#include "report/html_assets.h"  // generated from src/report/html/ (CMakeLists.txt)
#include "report/html_geometry.h"
#include "report/markup_escape.h"
#include "report/verdict.h"
#include "results/codec.h"
#include "tolerances.h"

namespace pd {

using json = nlohmann::ordered_json;

namespace {

struct Asset {
  std::string path, text;
};

// Where the inlined library is: $PDCHECK_THREE_DIR (three.min.js and
// OrbitControls.js in it), else the files CMake found at configure time.
std::vector<std::string> asset_paths() {
  if (const char* dir = std::getenv("PDCHECK_THREE_DIR"); dir && *dir)
    return {std::string(dir) + "/three.min.js", std::string(dir) + "/OrbitControls.js"};
  return {PDCHECK_THREE_JS, PDCHECK_ORBIT_CONTROLS_JS};
}

Asset read_asset(const std::string& path) {
  if (path.empty() || path.find("NOTFOUND") != std::string::npos)
    throw HtmlAssetError(
        "html: three.js was not found when pdcheck was configured (install Debian's libjs-three, "
        "e.g. by scripts/setup.sh, and re-run cmake; or set PDCHECK_THREE_DIR to a directory "
        "holding three.min.js and OrbitControls.js)");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || text.str().empty())
    throw HtmlAssetError("html: cannot read " + path +
                         ", which the page inlines (three.js from Debian's libjs-three: install "
                         "it, e.g. by scripts/setup.sh, or set PDCHECK_THREE_DIR)");
  return {path, text.str()};
}

// Text inlined in a <script> must not close it early.
std::string script_safe(std::string s) {
  for (size_t at = 0; (at = s.find("</", at)) != std::string::npos; at += 3)
    s.replace(at, 2, "<\\/");
  return s;
}

// JSON in a <script type="application/json">: '<' only occurs in strings,
// where \u003c means the same and cannot end the element.
std::string json_in_html(const json& j) {
  const std::string text = j.dump(-1, ' ', false, json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (char c : text) out += c == '<' ? std::string("\\u003c") : std::string(1, c);
  return out;
}

// One pass over the template: a value is never searched for placeholders (a
// part id of "{{DATA}}" stays text).
std::string fill_template(const std::string& page,
                          const std::map<std::string, std::string>& values) {
  std::string out;
  size_t at = 0;
  for (size_t open; (open = page.find("{{", at)) != std::string::npos;) {
    const size_t close = page.find("}}", open);
    const auto it = close == std::string::npos
                        ? values.end()
                        : values.find(page.substr(open + 2, close - open - 2));
    if (it == values.end()) {
      out.append(page, at, open + 2 - at);
      at = open + 2;
      continue;
    }
    out.append(page, at, open - at).append(it->second);
    at = close + 2;
  }
  return out.append(page, at, std::string::npos);
}

// Vertices as int16 steps of s (the largest coordinate / 32767: 1/65534 of the
// mesh's size, finer than a pixel) and triangles as uint16 (uint32 past 65,536
// vertices), little-endian: half the bytes of float32 and uint32.
json mesh_json(const std::string& label, const WebMesh& m) {
  float extent = 0.0f;
  for (float p : m.positions) extent = std::max(extent, std::fabs(p));
  const double step = extent > 0 ? extent / 32767.0 : 1.0;
  std::vector<std::int16_t> q(m.positions.size());
  for (size_t k = 0; k < q.size(); ++k)
    q[k] = static_cast<std::int16_t>(std::lround(m.positions[k] / step));
  const bool wide = m.vertex_count() > 65536;
  std::vector<std::uint16_t> narrow_idx;
  std::vector<std::uint32_t> wide_idx;
  for (const auto& t : m.triangles)
    for (unsigned v : t)
      wide ? wide_idx.push_back(v) : narrow_idx.push_back(static_cast<std::uint16_t>(v));
  json j = {{"label", label},
            {"o", {m.origin.x(), m.origin.y(), m.origin.z()}},
            {"s", step},
            {"v", base64(q.data(), q.size() * sizeof(std::int16_t))},
            {"t", wide ? base64(wide_idx.data(), wide_idx.size() * 4)
                       : base64(narrow_idx.data(), narrow_idx.size() * 2)},
            {"triangles", m.triangles.size()},
            {"how", m.how}};
  if (wide) j["t32"] = true;
  return j;
}

int status_rank(const std::string& s) {
  if (s == "interference") return 0;
  if (s == "clearance_violation") return 1;
  if (s == "undecided") return 2;
  if (s == "error") return 3;
  return 4;  // false_positive
}

// The sentence stderr, JUnit and SARIF give the pair (report/finding_text.h),
// from its report entry, so the page cannot say otherwise; baseline state and
// suppression are shown beside it. Empty for an entry that does not read back.
std::string pair_sentence(const json& p, const std::string& units, double tolerance) {
  try {
    std::vector<Part> two(2);
    two[0].id = p.at("a").get<std::string>();
    two[1].id = p.at("b").get<std::string>();
    return finding_text(pair_from_report(p, 0, 1), two, PairReview{}, units, tolerance);
  } catch (const std::exception&) {
    return "";
  }
}

double depth_of(const json& p) {
  return p.contains("depth") ? p["depth"].get<double>() : 0.0;
}

// Findings: every pair that is not separated, interference first, deeper first.
std::vector<const json*> sorted_findings(const json& report) {
  std::vector<const json*> findings;
  if (report.contains("pairs"))
    for (const json& p : report["pairs"])
      if (p.value("status", "") != "separated") findings.push_back(&p);
  std::stable_sort(findings.begin(), findings.end(), [](const json* x, const json* y) {
    const int rx = status_rank(x->value("status", "")), ry = status_rank(y->value("status", ""));
    return rx != ry ? rx < ry : depth_of(*x) > depth_of(*y);
  });
  return findings;
}

// A finding's row of the table: the report's keys the page shows, and its sentence.
json finding_row(const json& p, const json& report) {
  json row = {{"a", p.value("a", "")},
              {"b", p.value("b", "")},
              {"fingerprint", p.value("fingerprint", "")},
              {"status", p.value("status", "")}};
  for (const char* key :
       {"depth", "direction", "margin", "depth_source", "pieces", "confirmed", "error",
        "baseline_state", "suppressed", "warnings", "hull_depth", "depth_bounds", "distance",
        "clearance", "motion", "at", "reason", "group", "exact"})
    if (p.contains(key)) row[key] = p[key];
  if (row.contains("motion")) row["motion"].erase("series");
  row["text"] = pair_sentence(p, report.value("units", ""), report.value("tolerance", 0.0));
  return row;
}

// The page's geometry: each part's mesh once, the overlaps, the context boxes,
// within the page's triangle budget (tol::kHtmlPageTriangles).
class PageGeometry {
 public:
  explicit PageGeometry(const std::vector<Part>& parts) : parts_(parts) {
    for (const Part& p : parts) by_id_.emplace(p.id, &p);
  }
  bool spent() const { return budget_ == 0; }

  // The view of finding p: its parts' meshes, the overlap of what its depth is
  // measured on, and the context around it.
  json view_of(const json& p) {
    const std::string a = p.value("a", ""), b = p.value("b", "");
    json view = {{"a", mesh_of_part(a)}, {"b", mesh_of_part(b)}};
    const Part *pa = usable(a), *pb = usable(b);
    if (!pa || !pb) return view;
    if (depth_of(p) > 0) add_overlap(p, *pa, *pb, view);
    view["context"] = context_of(*pa, *pb);
    return view;
  }

  json meshes = json::array(), boxes = json::array();

 private:
  const Part* usable(const std::string& id) const {
    const auto it = by_id_.find(id);
    return it == by_id_.end() || it->second->error ? nullptr : it->second;
  }

  json add_mesh(const std::string& label, const WebMesh& m) {
    if (m.triangles.empty()) return nullptr;
    budget_ -= std::min(budget_, m.triangles.size());
    meshes.push_back(mesh_json(label, m));
    return static_cast<int>(meshes.size()) - 1;
  }

  json mesh_of_part(const std::string& id) {
    if (auto it = part_mesh_.find(id); it != part_mesh_.end())
      return it->second < 0 ? json(nullptr) : json(it->second);
    const auto found = by_id_.find(id);
    json index = nullptr;
    if (found != by_id_.end())
      index = add_mesh(id, part_web_mesh(*found->second, tol::kHtmlPartTriangles));
    part_mesh_[id] = index.is_null() ? -1 : index.get<int>();
    return index;
  }

  // The overlap drawn in red: the realising pieces' when the report names them
  // and the parts hold them; the parts' own solids' where a part is nonconvex
  // or the depth was measured on the parts themselves (never the hulls': a
  // 2 mm rim clash is not the whole slab the hulls share); else, both parts
  // convex (or taken as their hulls, pieces hull), the hulls'.
  void add_overlap(const json& p, const Part& pa, const Part& pb, json& view) {
    const Hull *ha = nullptr, *hb = nullptr;
    if (p.contains("pieces") && p["pieces"].is_array() && p["pieces"].size() == 2 &&
        p["pieces"][0].is_number_integer() && p["pieces"][1].is_number_integer()) {
      ha = realising_piece(pa, p["pieces"][0].get<int>());
      hb = realising_piece(pb, p["pieces"][1].get<int>());
      // A part of one piece is its own realising piece: drawn once, as the part.
      if (ha && hb && piece_count(pa) > 1)
        view["piece_a"] = add_mesh("piece", hull_web_mesh(ha->vertices, tol::kHtmlPartTriangles));
      if (ha && hb && piece_count(pb) > 1)
        view["piece_b"] = add_mesh("piece", hull_web_mesh(hb->vertices, tol::kHtmlPartTriangles));
    }
    const bool on_pieces = ha && hb;
    const std::string source = p.value("depth_source", "hull");
    if (!on_pieces &&
        (pa.convex == false || pb.convex == false || (source != "hull" && source != "pieces"))) {
      const SolidOverlap overlap = solid_overlap_web_mesh(pa, pb, tol::kHtmlPartTriangles);
      if (overlap.mesh) {
        view["overlap"] = add_mesh("overlap", *overlap.mesh);
        view["overlap_of"] = "the parts themselves";
      } else {
        view["overlap_note"] =
            overlap.note.empty() ? "the parts' surfaces do not cross" : overlap.note;
      }
      return;
    }
    const auto overlap =
        overlap_web_mesh(on_pieces ? ha->vertices : part_vertices(pa),
                         on_pieces ? hb->vertices : part_vertices(pb), tol::kHtmlPartTriangles);
    if (overlap) {
      view["overlap"] = add_mesh("overlap", *overlap);
      view["overlap_of"] = on_pieces                                ? "the realising pieces"
                           : pa.convex == true && pb.convex == true ? "the parts (both convex)"
                                                                    : "the convex hulls";
    }
  }

  // The rest of the assembly around a pair, faint in its view: the boxes of the
  // parts whose boxes meet the pair's box grown by half its diagonal, the
  // kHtmlContextParts nearest, each box stored once.
  json context_of(const Part& a, const Part& b) {
    const Aabb pair = a.box.merged(b.box);
    const Aabb near = pair.inflated(0.5 * (pair.hi - pair.lo).norm());
    const Vec3 centre = (pair.lo + pair.hi) / 2;
    std::vector<std::pair<double, const Part*>> found;
    for (const Part& p : parts_)
      if (&p != &a && &p != &b && !p.error && p.box.overlaps(near))
        found.push_back({((p.box.lo + p.box.hi) / 2 - centre).squaredNorm(), &p});
    const size_t keep = std::min(found.size(), tol::kHtmlContextParts);
    std::partial_sort(found.begin(), found.begin() + static_cast<long>(keep), found.end());
    json ids = json::array();
    for (size_t k = 0; k < keep; ++k) {
      const Part* p = found[k].second;
      auto [it, added] = box_index_.emplace(p, static_cast<int>(boxes.size()));
      if (added)
        boxes.push_back({p->id,
                         {static_cast<float>(p->box.lo.x()), static_cast<float>(p->box.lo.y()),
                          static_cast<float>(p->box.lo.z()), static_cast<float>(p->box.hi.x()),
                          static_cast<float>(p->box.hi.y()), static_cast<float>(p->box.hi.z())}});
      ids.push_back(it->second);
    }
    return ids;
  }

  const std::vector<Part>& parts_;
  std::map<std::string, const Part*> by_id_;
  std::map<std::string, int> part_mesh_;  ///< part id → index in meshes (−1: none)
  std::map<const Part*, int> box_index_;
  size_t budget_ = tol::kHtmlPageTriangles;
};

json part_errors_of(const json& report) {
  json part_errors = json::array();
  if (report.contains("parts"))
    for (const json& p : report["parts"])
      if (p.contains("error")) part_errors.push_back({{"id", p["id"]}, {"error", p["error"]}});
  return part_errors;
}

// The banner: pass, fail or incomplete, from the summary (report/verdict.h).
json verdict_json(const json& report) {
  const Verdict v = run_verdict(report.value("summary", json::object()));
  json j = {{"state", v.state}, {"headline", v.headline}, {"counts", v.counts}};
  if (report.contains("shard") && report["shard"].is_object())
    j["shard"] = "shard " + std::to_string(report["shard"].value("index", 0)) + " of " +
                 std::to_string(report["shard"].value("total", 0)) +
                 ": the run's verdict is its merge's (pdcheck merge)";
  return j;
}

// What the page's script reads: the report's summary, the rows and the geometry.
json page_data(const json& report, json rows, PageGeometry& geometry,
               const std::vector<std::string>& notes) {
  json data = {
      {"tool", report.value("tool", json::object())},
      {"scene", report.value("scene", "")},
      {"units", report.value("units", "")},
      {"tolerance", report.value("tolerance", 0.0)},
      {"method", report.value("method", json::object())},
      {"seconds", report.value("seconds", 0.0)},
      {"summary", report.value("summary", json::object())},
      {"verdict", verdict_json(report)},
      {"findings", std::move(rows)},
      {"meshes", std::move(geometry.meshes)},
      {"boxes", std::move(geometry.boxes)},
      {"part_errors", part_errors_of(report)},
      {"notes", notes},
      {"caps",
       {{"part_triangles", tol::kHtmlPartTriangles}, {"page_triangles", tol::kHtmlPageTriangles}}}};
  if (report.contains("stage_seconds")) data["stage_seconds"] = report["stage_seconds"];
  if (report.contains("groups")) data["groups"] = report["groups"];
  if (report.contains("baseline")) data["baseline_file"] = report["baseline"].value("file", "");
  return data;
}

}  // namespace

void check_html_assets() {
  for (const auto& path : asset_paths()) read_asset(path);
}

std::string render_html(const json& report, const std::vector<Part>& parts,
                        const std::vector<std::string>& notes_in) {
  std::vector<Asset> assets;
  for (const auto& path : asset_paths()) assets.push_back(read_asset(path));
  PageGeometry geometry(parts);
  json rows = json::array();
  size_t skipped = 0;
  for (const json* p : sorted_findings(report)) {
    json row = finding_row(*p, report);
    if (geometry.spent()) ++skipped;
    row["view"] = geometry.spent() ? json(nullptr) : geometry.view_of(*p);
    rows.push_back(std::move(row));
  }
  std::vector<std::string> notes = notes_in;
  if (skipped)
    notes.push_back(std::to_string(skipped) +
                    " findings have no 3D view: the page's geometry "
                    "budget (" +
                    std::to_string(tol::kHtmlPageTriangles) +
                    " triangles) went to the findings listed first");
  const json data = page_data(report, std::move(rows), geometry, notes);
  const std::string title = "pdcheck: " + report.value("scene", std::string("report"));
  return fill_template(kHtmlPage,
                       {{"TITLE", markup_escape(title)},
                        {"STYLE", kHtmlStyle},
                        {"LICENCE", markup_escape(kThreeLicence)},
                        {"DATA", json_in_html(data)},
                        {"THREE", script_safe(assets[0].text) + "\n" + script_safe(assets[1].text)},
                        {"SCRIPT", script_safe(kHtmlScript)}});
}

std::string render_html(const ReportInput& in) {
  return render_html(report_document(in), in.run.parts);
}

}  // namespace pd
