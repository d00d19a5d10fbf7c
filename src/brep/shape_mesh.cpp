#include "brep/shape_mesh.h"

#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "brep/face_sag.h"

namespace pd {

namespace {

// The mesher's angular deflection (radians): OCCT's default. The linear
// deflection decides the chord error; the angle only keeps large, gently
// curved faces from coming out coarser in angle than this.
constexpr double kMeshAngle = 0.5;

// Global vertex ids for one shape: a vertex is one id, an edge's k-th polygon
// point (0 < k < n − 1) is one id, every other face node its own. Vertices and
// edges are told apart as shapes (IsSame: the same TShape at the same location).
class Welder {
 public:
  explicit Welder(const TopoDS_Shape& shape) {
    TopExp::MapShapes(shape, TopAbs_VERTEX, vertices_);
    TopExp::MapShapes(shape, TopAbs_EDGE, edges_);
  }
  int vertex(const TopoDS_Vertex& v, const gp_Pnt& p) {
    const int k = vertices_.FindIndex(v);
    auto [it, fresh] = by_vertex_.emplace(k, 0);
    if (fresh) it->second = add(p);
    return it->second;
  }
  int edge_point(const TopoDS_Edge& e, int k, const gp_Pnt& p) {
    // By the edge as a shape (its geometry and its location), not its TShape
    // alone: a cylinder's two circles may be one TShape at two locations.
    auto [it, fresh] = by_edge_.emplace(std::make_pair(edges_.FindIndex(e), k), 0);
    if (fresh) it->second = add(p);
    return it->second;
  }
  int add(const gp_Pnt& p) {
    points_.push_back(p);
    return int(points_.size()) - 1;
  }
  Points points() const {
    Points out(3, long(points_.size()));
    for (size_t k = 0; k < points_.size(); ++k)
      out.col(long(k)) = Vec3(points_[k].X(), points_[k].Y(), points_[k].Z());
    return out;
  }

 private:
  TopTools_IndexedMapOfShape vertices_, edges_;
  std::map<int, int> by_vertex_;
  std::map<std::pair<int, int>, int> by_edge_;
  std::vector<gp_Pnt> points_;
};

long odd_edges(const Triangles& t) {
  std::map<std::pair<int, int>, int> count;
  for (long k = 0; k < t.cols(); ++k)
    for (int c = 0; c < 3; ++c) {
      const int a = t(c, k), b = t((c + 1) % 3, k);
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  long odd = 0;
  for (const auto& [edge, n] : count) odd += n % 2;
  return odd;
}

}  // namespace

ShapeMesh mesh_solids(const TopoDS_Shape& shape, double deflection, bool in_parallel) {
  ShapeMesh out;
  out.tessellation.deflection = deflection;
  if (!(deflection > 0)) {  // the names and solids alone
    for (TopExp_Explorer solid(shape, TopAbs_SOLID); solid.More(); solid.Next()) ++out.solids;
    return out;
  }
  BRepTools::Clean(shape);  // a mesh the file carried would be reused as it is
  IMeshTools_Parameters params;
  params.Deflection = deflection;
  params.Angle = kMeshAngle;
  params.InParallel = in_parallel;
  BRepMesh_IncrementalMesh mesher(shape, params);

  Welder weld(shape);
  std::vector<std::array<int, 3>> triangles;
  double tolerance = 0.0;
  for (TopExp_Explorer x(shape, TopAbs_VERTEX); x.More(); x.Next())
    tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Vertex(x.Current())));
  for (TopExp_Explorer solid(shape, TopAbs_SOLID); solid.More(); solid.Next()) {
    ++out.solids;
    for (TopExp_Explorer x(solid.Current(), TopAbs_FACE); x.More(); x.Next()) {
      const TopoDS_Face face = TopoDS::Face(x.Current());
      tolerance = std::max(tolerance, BRep_Tool::Tolerance(face));
      TopLoc_Location loc;
      const Handle(Poly_Triangulation)& t = BRep_Tool::Triangulation(face, loc);
      ++out.tessellation.faces;
      if (t.IsNull() || t->NbTriangles() == 0) continue;  // a face the mesher could not mesh
      const gp_Trsf to_shape = loc.Transformation();
      std::vector<int> id(size_t(t->NbNodes()) + 1, -1);
      for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
        const TopoDS_Edge edge = TopoDS::Edge(ex.Current());
        tolerance = std::max(tolerance, BRep_Tool::Tolerance(edge));
        const Handle(Poly_PolygonOnTriangulation)& poly =
            BRep_Tool::PolygonOnTriangulation(edge, t, loc);
        if (poly.IsNull()) continue;
        const int n = poly->NbNodes();
        TopoDS_Vertex first, last;
        TopExp::Vertices(edge, first, last);  // in the edge's parameter order
        for (int k = 1; k <= n; ++k) {
          const int node = poly->Node(k);
          const gp_Pnt p = t->Node(node).Transformed(to_shape);
          if (k == 1 && !first.IsNull())
            id[node] = weld.vertex(first, p);
          else if (k == n && !last.IsNull())
            id[node] = weld.vertex(last, p);
          else
            id[node] = weld.edge_point(edge, k, p);
        }
      }
      for (int k = 1; k <= t->NbNodes(); ++k)
        if (id[k] < 0) id[k] = weld.add(t->Node(k).Transformed(to_shape));
      const bool reversed = face.Orientation() == TopAbs_REVERSED;
      for (int k = 1; k <= t->NbTriangles(); ++k) {
        int a, b, c;
        t->Triangle(k).Get(a, b, c);
        if (reversed) std::swap(b, c);
        const std::array<int, 3> tri{id[a], id[b], id[c]};
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;  // at a pole
        triangles.push_back(tri);
      }
      const FaceSag sag = face_sag(face, t, loc);
      out.tessellation.sag = std::max(out.tessellation.sag, sag.value);
      out.triangle_sags.resize(triangles.size(), sag.value);  // this face's triangles
      if (!sag.bound) {
        ++out.tessellation.free_form;
        out.tessellation.basis = SagBasis::kEstimate;
      }
    }
  }
  out.tessellation.tolerance = tolerance;
  out.mesh.vertices = weld.points();
  out.mesh.triangles.resize(3, long(triangles.size()));
  for (size_t k = 0; k < triangles.size(); ++k)
    for (int c = 0; c < 3; ++c) out.mesh.triangles(c, long(k)) = triangles[k][size_t(c)];
  out.open_edges = odd_edges(out.mesh.triangles);
  return out;
}

}  // namespace pd
