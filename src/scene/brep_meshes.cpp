// B-rep files as the mesh loader hands files over (scene/mesh_loader.h):
// their leaf instances as meshes named by node paths.
#include <cstdio>
#include <stdexcept>

#include "hash.h"
#include "scene/mesh_loader.h"
#include "scene/node_names.h"

namespace pd {

namespace {

// Every node's path segment among its siblings, and the leaves' paths: from
// the free shapes down when the file has several, else from the one free
// shape's components (as assimp's unnamed root), the one free shape's own name
// when it is a leaf itself (a part file).
std::vector<std::string> leaf_paths(const BrepFile& f) {
  std::vector<std::vector<int>> children(f.nodes.size() + 1);  // [0]: the roots
  for (size_t k = 0; k < f.nodes.size(); ++k)
    children[size_t(f.nodes[k].parent + 1)].push_back(int(k));
  std::vector<std::string> segment(f.nodes.size());
  for (const std::vector<int>& siblings : children) {
    std::vector<std::string> names;
    for (int k : siblings) names.push_back(f.nodes[size_t(k)].name);
    const std::vector<std::string> s = sibling_segments(names);
    for (size_t i = 0; i < siblings.size(); ++i) segment[size_t(siblings[i])] = s[i];
  }
  const bool one_root = children[0].size() == 1;
  std::vector<std::string> path(f.nodes.size());
  std::vector<std::string> out(f.leaves.size());
  for (size_t k = 0; k < f.nodes.size(); ++k) {  // parents come before their children
    const int parent = f.nodes[k].parent;
    if (parent < 0)
      path[k] = one_root && f.nodes[k].leaf < 0 ? "" : segment[k];
    else
      path[k] = path[size_t(parent)].empty() ? segment[k] : path[size_t(parent)] + "/" + segment[k];
    if (f.nodes[k].leaf >= 0) out[size_t(f.nodes[k].leaf)] = path[k];
  }
  return out;
}

}  // namespace

NodeMeshes load_brep_meshes(const std::string& path, double deflection, bool by_node,
                            std::vector<std::string>* warnings, int threads) {
  BrepFile f;
  try {
    f = read_brep_file(path, deflection, threads);
  } catch (const std::exception& e) {
    throw MeshError(std::string("cannot load ") + e.what());
  }
  if (warnings) warnings->insert(warnings->end(), f.warnings.begin(), f.warnings.end());
  NodeMeshes out;
  out.nodes = leaf_paths(f);
  for (BrepLeaf& l : f.leaves) {
    out.meshes.push_back(std::move(l.mesh));
    out.tessellations.push_back(l.tessellation);
    out.triangle_sags.push_back(std::move(l.triangle_sags));
    out.leaf_errors.push_back(l.error.value_or(""));
  }
  return by_node ? out : join_brep_leaves(std::move(out));
}

std::string brep_read_key(const std::string& path, double deflection) {
  char d[32];
  std::snprintf(d, sizeof d, "%.17g|", deflection);
  return d + path;
}

std::string brep_read_cache_key(const std::string& path, const std::string& content_hash,
                                double deflection) {
  return Hasher()
      .add("pdcheck-brep-read-1")
      .add(brep_mesh_version())
      .add(path)
      .add(content_hash)
      .add(deflection)
      .hex();
}

NodeMeshes join_brep_leaves(NodeMeshes by_node) {
  NodeMeshes out;
  Tessellation t;
  std::vector<float> sags;  // in join_meshes' order: the leaves' triangles one after another
  for (size_t k = 0; k < by_node.meshes.size(); ++k) {
    if (!by_node.leaf_errors[k].empty()) throw MeshError(by_node.leaf_errors[k]);
    t = k == 0 ? by_node.tessellations[k] : combine(t, by_node.tessellations[k]);
    sags.insert(sags.end(), by_node.triangle_sags[k].begin(), by_node.triangle_sags[k].end());
  }
  out.meshes = {join_meshes(by_node.meshes)};
  out.tessellations = {t};
  if (long(sags.size()) == out.meshes[0].triangles.cols()) out.triangle_sags = {std::move(sags)};
  out.leaf_errors = {""};
  return out;
}

}  // namespace pd
