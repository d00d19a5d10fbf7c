#include "brep/brep_file.h"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <unistd.h>

#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <stdexcept>

#include "brep/occt_backend.h"
#include "brep/shape_mesh.h"
#include "brep/shape_tree.h"

namespace pd {

namespace {

BrepLeaf placed_leaf(const ShapeTree::Leaf& l, const ShapeMesh& m) {
  BrepLeaf leaf;
  leaf.solids = m.solids;
  leaf.tessellation = m.tessellation;
  leaf.tessellation.sag *= std::abs(l.place.ScaleFactor());
  leaf.triangle_sags.reserve(m.triangle_sags.size());
  for (double s : m.triangle_sags) {
    s *= std::abs(l.place.ScaleFactor());
    float f = float(s);
    if (double(f) < s) f = std::nextafter(f, INFINITY);  // never below the face's
    leaf.triangle_sags.push_back(f);
  }
  leaf.tessellation.deflection = m.tessellation.deflection;
  leaf.mesh.triangles = m.mesh.triangles;
  leaf.mesh.vertices.resize(3, m.mesh.vertices.cols());
  for (long k = 0; k < m.mesh.vertices.cols(); ++k) {
    gp_XYZ p(m.mesh.vertices(0, k), m.mesh.vertices(1, k), m.mesh.vertices(2, k));
    l.place.Transforms(p);
    leaf.mesh.vertices.col(k) = Vec3(p.X(), p.Y(), p.Z());
  }
  const std::string name = "\"" + l.name_path + "\"";
  if (m.solids == 0)
    leaf.error = name + " holds no solid (a surface model: shells or faces only); pdcheck " +
                 "checks solids";
  return leaf;
}

// Whether two of `products` share a face: the mesher stores a face's
// triangulation in the face itself, so such products are meshed one by one.
bool share_faces(const std::vector<const TopoDS_Shape*>& products) {
  std::set<const TopoDS_TShape*> seen;
  for (const TopoDS_Shape* p : products) {
    std::set<const TopoDS_TShape*> own;
    for (TopExp_Explorer x(*p, TopAbs_FACE); x.More(); x.Next())
      own.insert(x.Current().TShape().get());
    for (const TopoDS_TShape* f : own)
      if (!seen.insert(f).second) return true;
  }
  return false;
}

}  // namespace

BrepFile occt_read_brep_file(const std::string& path, double deflection, int threads) {
  if (::access(path.c_str(), R_OK) != 0)
    throw std::runtime_error("B-rep file " + path + ": cannot be read");
  try {
    const ShapeTree tree = read_shape_tree(path);
    BrepFile out;
    out.nodes = tree.nodes;
    out.unit = tree.unit;
    std::map<std::string, ShapeMesh> meshed;  // each product once
    std::vector<const TopoDS_Shape*> products;
    std::vector<ShapeMesh*> into;
    for (const ShapeTree::Leaf& l : tree.leaves) {
      const auto [it, fresh] = meshed.emplace(l.product_key, ShapeMesh{});
      if (!fresh) continue;
      products.push_back(&l.product);
      into.push_back(&it->second);
    }
    // Products side by side, and each one's faces too, in one TBB arena of
    // `threads`: Open CASCADE's parallel loops run on TBB, so the mesher's
    // loops inside a product share the arena's threads with the products'
    // (work stealing: a large product's faces take the threads the small
    // ones leave), and never more threads than asked.
    const auto mesh = [&](size_t k, bool in_parallel) {
      *into[k] = mesh_solids(*products[k], deflection, in_parallel);
    };
    // No more than the cores this process may run on (TBB warns past them).
    threads = std::min(threads, tbb::this_task_arena::max_concurrency());
    if (threads > 1 && !share_faces(products)) {
      tbb::task_arena arena(threads);
      arena.execute(
          [&] { tbb::parallel_for(size_t(0), products.size(), [&](size_t k) { mesh(k, true); }); });
    } else {
      for (size_t k = 0; k < products.size(); ++k) mesh(k, false);
    }
    for (const ShapeTree::Leaf& l : tree.leaves) {
      const auto it = meshed.find(l.product_key);
      out.leaves.push_back(placed_leaf(l, it->second));
      if (it->second.open_edges > 0 && it->second.solids > 0)
        out.warnings.push_back("\"" + l.name_path + "\": its mesh has " +
                               std::to_string(it->second.open_edges) +
                               " open edges (a solid whose faces do not close)");
    }
    for (std::string& w : out.warnings) w = "B-rep file " + path + ": " + w;
    for (BrepLeaf& l : out.leaves)
      if (l.error) l.error = "B-rep file " + path + ": " + *l.error;
    return out;
  } catch (const Standard_Failure& e) {
    throw std::runtime_error("B-rep file " + path +
                             ": Open CASCADE failed: " + e.GetMessageString());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("B-rep file " + path + ": " + e.what());
  }
}

}  // namespace pd
