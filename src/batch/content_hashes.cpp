#include "batch/content_hashes.h"

#include <cstdint>
#include <map>

#include "file_hash.h"
#include "hash.h"
#include "solve/settings.h"
#include "tolerances.h"

namespace pd {

namespace {

void add_vec(Hasher& h, const Vec3& v) {
  for (int k = 0; k < 3; ++k) h.add(v[k]);
}

}  // namespace

std::map<std::string, std::string> mesh_file_hashes(const SceneSpec& scene) {
  std::map<std::string, std::string> files;
  for (const PartSpec& p : scene.parts)
    if (p.mesh && !files.count(*p.mesh)) files.emplace(*p.mesh, file_content_hash(*p.mesh));
  return files;
}

std::vector<std::string> part_content_hashes(const SceneSpec& scene) {
  return part_content_hashes(scene, mesh_file_hashes(scene));
}

std::vector<std::string> part_content_hashes(const SceneSpec& scene,
                                             const std::map<std::string, std::string>& files) {
  std::vector<std::string> out;
  out.reserve(scene.parts.size());
  for (const PartSpec& p : scene.parts) {
    Hasher h;
    h.add("pdcheck-part-v1");
    if (p.mesh) {
      const auto it = files.find(*p.mesh);
      h.add("mesh").add(it != files.end() ? it->second : file_content_hash(*p.mesh));
      // A node part: the node path too (a part of another node is other
      // geometry). Added only then: other parts' hashes stay as they were.
      if (p.node) h.add("node").add(*p.node);
    } else {
      // The list's own digest, which a shard holds without the list (VertexSummary).
      // Mesh parts hash as before; an inline part's hash differs from the
      // versions that hashed the bits themselves (--reuse then solves it again).
      if (p.vertex_summary)
        h.add("inline").add(std::string_view(p.vertex_summary->digest.data(), 32));
      else
        h.add("inline").add(vertex_digest(*p.vertices));
    }
    h.add(p.to_scene_units);
    for (int i = 0; i < 16; ++i) h.add(p.transform(i / 4, i % 4));
    h.add(pieces_name(p.pieces));
    if (p.motion) {
      h.add("motion");
      add_vec(h, p.motion->angular);
      add_vec(h, p.motion->about);
      add_vec(h, p.motion->velocity);
    }
    out.push_back(h.hex());
  }
  return out;
}

std::string scene_content_hash(const SceneSpec& scene,
                               const std::vector<std::string>& part_hashes) {
  Hasher h;
  h.add("pdcheck-scene-v1").add(scene.units.value_or("mm"));
  for (size_t k = 0; k < scene.parts.size(); ++k) h.add(scene.parts[k].id).add(part_hashes[k]);
  if (scene.pairs) {
    h.add("pairs");
    for (const auto& [a, b] : *scene.pairs) h.add(a).add(b);
  }
  return h.hex();
}

namespace {

struct AddSetting {
  Hasher& h;
  void operator()(const Setting&, Method m) const { h.add(method_name(m)); }
  void operator()(const Setting&, std::uint64_t v) const { h.add(std::to_string(v)); }
  void operator()(const Setting&, int v) const { h.add(std::to_string(v)); }
  void operator()(const Setting&, double v) const { h.add(v); }
};

}  // namespace

void add_solver_settings(Hasher& h, const SolverSettings& s) {
  for_each_setting(s, AddSetting{h});
  // Not in for_each_setting (no scene, CLI or report key; off only in tests),
  // and hashed only when off, so the default's hashes stay what they were.
  if (!s.epa) h.add("no-epa");
}

std::string settings_hash(const SolverSettings& s, double tolerance, const Checks& checks,
                          const std::optional<AutoTolerance>& auto_tolerance) {
  Hasher h;
  h.add("pdcheck-settings-v1");
  add_solver_settings(h, s);
  h.add(tolerance);
  if (auto_tolerance) {
    h.add("tolerance-auto").add(auto_tolerance->min.value_or(-1.0));
    h.add(auto_tolerance->max.value_or(-1.0)).add(tol::kAutoToleranceMargin);
  }
  if (checks.clearance) {
    h.add("clearance").add(checks.clearance->min);
    for (const auto& e : checks.clearance->pairs) h.add(e.a).add(e.b).add(e.min);
  }
  if (checks.motion) {
    const TimeGrid& g = checks.motion->grid;
    h.add("motion").add(g.t0).add(g.t1).add(g.dt).add(checks.motion->series ? "series" : "");
  }
  return h.hex();
}

}  // namespace pd
