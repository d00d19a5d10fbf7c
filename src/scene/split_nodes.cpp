#include "scene/split_nodes.h"

#include <map>
#include <memory>

#include "file_hash.h"
#include "scene/node_names.h"
#include "scene/node_names_cache.h"

namespace pd {

namespace {

// A clash between a node part and another part: both named, as written.
[[noreturn]] void clash(const PartSpec& first, const PartSpec& second) {
  throw SceneError(second.where + ": part id \"" + second.id + "\" is also the id of " +
                   first.where + ": ids must be unique in the scene (a split part's node parts " +
                   "are named \"<part id>/<node path>\")");
}

// The parts that stayed whole because their file could not be read.
std::vector<const PartSpec*> failed_splits(const SceneSpec& s) {
  std::vector<const PartSpec*> out;
  for (const PartSpec& p : s.parts)
    if (p.split_nodes && p.error) out.push_back(&p);
  return out;
}

// `id` if it lies under a failed split part, that part's id; else `id`.
std::string whole_id(const std::vector<const PartSpec*>& failed, const std::string& id) {
  for (const PartSpec* p : failed)
    if (id.size() > p->id.size() + 1 && id[p->id.size()] == '/' &&
        id.compare(0, p->id.size(), p->id) == 0)
      return p->id;
  return id;
}

// A listed pair or clearance that names a node of an unreadable file names the
// file's part instead: the pair is then an error, as the part's pairs are,
// where an unknown id would refuse the whole scene. A pair of two such nodes
// of one file is the part's own error, reported once.
void name_failed_splits(SceneSpec& s) {
  const std::vector<const PartSpec*> failed = failed_splits(s);
  if (failed.empty()) return;
  if (s.pairs) {
    std::vector<std::pair<std::string, std::string>> kept;
    for (const auto& [a, b] : *s.pairs) {
      std::pair<std::string, std::string> p{whole_id(failed, a), whole_id(failed, b)};
      if (p.first != p.second) kept.push_back(std::move(p));
    }
    s.pairs = std::move(kept);
  }
  if (s.checks.clearance)
    for (ClearanceCheck::PerPair& p : s.checks.clearance->pairs) {
      p.a = whole_id(failed, p.a);
      p.b = whole_id(failed, p.b);
    }
}

}  // namespace

bool under_unsplit_part(const SceneSpec& s, const std::string& id) {
  for (const PartSpec& p : s.parts)
    if (p.split_nodes && !p.error && id.size() > p.id.size() + 1 && id[p.id.size()] == '/' &&
        id.compare(0, p.id.size(), p.id) == 0)
      return true;
  return false;
}

void split_node_parts(SceneSpec& s, const SplitLoad& load) {
  // Each distinct file read once, whatever the parts splitting it, unless the
  // cache holds its node paths (keyed by its content: a changed file misses).
  std::map<std::string, LoadedMeshes> files;
  std::vector<MeshRequest> requests;
  std::vector<std::string> hashes;  // per request, its file's content hash when cached
  for (const PartSpec& p : s.parts) {
    if (!p.split_nodes || !p.mesh || files.count(*p.mesh)) continue;
    LoadedMeshes& f = files[*p.mesh];
    const std::string hash = load.cache_dir.empty() ? "" : file_content_hash(*p.mesh);
    if (!hash.empty())
      if (auto hit = read_cached_node_names(load.cache_dir, node_names_key(hash))) {
        f.nodes = std::move(*hit);
        continue;
      }
    // A B-rep file is read whole, meshed at its parts' deflection: reading it
    // is most of meshing it, and the parts stage takes it from here.
    const double deflection = file_deflection(s, p);
    requests.push_back(
        {*p.mesh, true, true, deflection == 0, deflection, load.keep_mb * 1048576.0});
    if (deflection > 0 && !hash.empty()) {  // a B-rep file: a rerun meshes nothing
      requests.back().read_cache_dir = load.cache_dir;
      requests.back().read_cache_key = brep_read_cache_key(*p.mesh, hash, deflection);
    }
    hashes.push_back(hash);
  }
  if (files.empty()) return;
  if (load.on_files && !requests.empty()) load.on_files(requests.size());
  std::vector<LoadedMeshes> read = load_meshes_isolated(
      requests, load.threads, load.timeout, load.memory_mb, load.before_load, load.on_read);
  auto whole = std::make_shared<std::map<std::string, LoadedMeshes>>();
  for (size_t r = 0; r < read.size(); ++r) {
    LoadedMeshes& got = read[r];
    // Kept whole (unless too large: names only came back); the split takes the names.
    if (!requests[r].node_names_only && !got.error && !got.meshes.empty()) {
      LoadedMeshes names;
      for (const std::string& n : got.nodes)  // a node's meshes come together
        if (names.nodes.empty() || names.nodes.back() != n) names.nodes.push_back(n);
      whole->emplace(brep_read_key(requests[r].path, requests[r].deflection), std::move(got));
      got = std::move(names);
    }
    if (!got.error && !hashes[r].empty())
      write_cached_node_names(load.cache_dir, node_names_key(hashes[r]), got.nodes);
    files[requests[r].path] = std::move(got);
  }
  if (!whole->empty()) s.brep_reads = whole;

  std::vector<PartSpec> parts;
  parts.reserve(s.parts.size());
  for (PartSpec& p : s.parts) {
    if (!p.split_nodes) {
      parts.push_back(std::move(p));
      continue;
    }
    const LoadedMeshes& file = files.at(*p.mesh);
    if (p.split_auto && !file.error && file.nodes.size() == 1) {  // a B-rep part file: whole
      p.split_nodes = false;
      parts.push_back(std::move(p));
      continue;
    }
    if (file.error || file.nodes.empty()) {
      // One part, named by its id, carries why: its pairs are errors, the batch goes on.
      p.error = file.error ? *file.error : "mesh file " + *p.mesh + ": has no meshes";
      parts.push_back(std::move(p));
      continue;
    }
    for (const std::string& node : file.nodes) {
      PartSpec n = p;
      n.split_nodes = false;
      n.id = node_part_id(p.id, node);
      n.group = node_part_group(p.group, node);
      n.node = node;
      n.where = p.where + " node \"" + node + "\"";
      parts.push_back(std::move(n));
    }
  }
  s.parts = std::move(parts);
  name_failed_splits(s);

  std::map<std::string, size_t> ids;
  for (size_t k = 0; k < s.parts.size(); ++k) {
    const auto [it, fresh] = ids.emplace(s.parts[k].id, k);
    if (!fresh) clash(s.parts[it->second], s.parts[k]);
  }
  validate_scene(s);
}

}  // namespace pd
