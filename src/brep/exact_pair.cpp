#include "brep/exact_pair.h"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <Bnd_OBB.hxx>
#include <GProp_GProps.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <gp_Ax3.hxx>
#include <map>
#include <memory>

#include "brep/occt_backend.h"
#include "brep/shape_tree.h"
#include "tolerances.h"

namespace pd {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// A progress indicator that asks the algorithm to stop at a deadline: how an
// Open CASCADE Boolean is time-boxed without killing its process.
class Deadline : public Message_ProgressIndicator {
 public:
  explicit Deadline(Clock::time_point at) : at_(at) {}
  Standard_Boolean UserBreak() override { return Clock::now() > at_; }
  void Show(const Message_ProgressScope&, const Standard_Boolean) override {}

 private:
  Clock::time_point at_;
};

// Every file read in this process (a worker measures many pairs).
const ShapeTree& tree_of(const std::string& file) {
  static std::map<std::string, std::unique_ptr<ShapeTree>> trees;
  auto it = trees.find(file);
  if (it == trees.end())
    it = trees.emplace(file, std::make_unique<ShapeTree>(read_shape_tree(file))).first;
  return *it->second;
}

// A part's solids placed in the scene, in millimetres scaled by `to_mm`:
// Open CASCADE's confusion tolerance (1e-7) is meant for model units of that size.
struct PlacedSolids {
  std::vector<TopoDS_Solid> solids;
  std::vector<Bnd_Box> boxes;
  /// Per solid, its faces and each face's box from its exact geometry
  /// (BRepBndLib::Add without the triangulation: a free-form face's box holds
  /// its control net, which holds the face): distances are sought only
  /// between faces whose boxes can hold a nearer pair.
  struct Face {
    TopoDS_Face face;
    Bnd_Box box;
  };
  std::vector<std::vector<Face>> faces;
};

gp_Trsf to_trsf(const Mat4& m, double to_mm) {
  gp_Trsf t;
  // SetValues accepts a rotation times a uniform scale, and throws otherwise.
  t.SetValues(to_mm * m(0, 0), to_mm * m(0, 1), to_mm * m(0, 2), to_mm * m(0, 3), to_mm * m(1, 0),
              to_mm * m(1, 1), to_mm * m(1, 2), to_mm * m(1, 3), to_mm * m(2, 0), to_mm * m(2, 1),
              to_mm * m(2, 2), to_mm * m(2, 3));
  return t;
}

PlacedSolids place_solids(const ExactPart& p, double to_mm) {
  const ShapeTree& tree = tree_of(p.file);
  if (p.leaf >= int(tree.leaves.size()))
    throw std::runtime_error("the file has no leaf " + std::to_string(p.leaf) +
                             " (it changed since it was read?)");
  std::vector<const ShapeTree::Leaf*> leaves;
  if (p.leaf >= 0)
    leaves.push_back(&tree.leaves[size_t(p.leaf)]);
  else
    for (const ShapeTree::Leaf& l : tree.leaves) leaves.push_back(&l);
  const gp_Trsf scene = to_trsf(p.placement, to_mm);
  PlacedSolids out;
  for (const ShapeTree::Leaf* l : leaves) {
    const gp_Trsf t = scene.Multiplied(l->place);
    TopoDS_Shape s;
    if (std::abs(t.ScaleFactor() - 1.0) < 1e-12)
      s = l->product.Moved(TopLoc_Location(t));
    else
      s = BRepBuilderAPI_Transform(l->product, t, Standard_True).Shape();
    for (TopExp_Explorer x(s, TopAbs_SOLID); x.More(); x.Next()) {
      const TopoDS_Solid solid = TopoDS::Solid(x.Current());
      out.solids.push_back(solid);
      Bnd_Box b;
      std::vector<PlacedSolids::Face> faces;
      for (TopExp_Explorer f(solid, TopAbs_FACE); f.More(); f.Next()) {
        Bnd_Box fb;
        BRepBndLib::Add(f.Current(), fb, Standard_False);
        fb.Enlarge(BRep_Tool::Tolerance(TopoDS::Face(f.Current())));
        b.Add(fb);
        faces.push_back({TopoDS::Face(f.Current()), fb});
      }
      out.boxes.push_back(b);
      out.faces.push_back(std::move(faces));
    }
  }
  return out;
}

// A part's placed solids, made once per process (a worker measures its pairs
// one after another; a part's pairs run together).
const PlacedSolids& placed_solids(const ExactPart& p, double to_mm) {
  static std::map<std::string, std::unique_ptr<PlacedSolids>> placed;
  std::string key = p.file + '\0' + std::to_string(p.leaf) + '\0' + std::to_string(to_mm);
  key.append(reinterpret_cast<const char*>(p.placement.data()), sizeof(double) * 16);
  auto it = placed.find(key);
  if (it == placed.end())
    it = placed.emplace(key, std::make_unique<PlacedSolids>(place_solids(p, to_mm))).first;
  return *it->second;
}

// Which of `s` holds `p` strictly inside (-1: none).
int inside(const PlacedSolids& s, const gp_Pnt& p, long& calls) {
  for (size_t k = 0; k < s.solids.size(); ++k) {
    if (s.boxes[k].IsOut(p)) continue;
    ++calls;
    BRepClass3d_SolidClassifier c(s.solids[k], p, 1e-9);
    if (c.State() == TopAbs_IN) return int(k);
  }
  return -1;
}

// The smallest distance between a shape and some faces (each with its exact
// box), and the nearest point on them: faces are measured nearest box first,
// until no box is nearer than the best distance found (a box holds its face,
// so no face beyond it can be nearer). `box` is the shape's own.
double nearest_face(const TopoDS_Shape& shape, const Bnd_Box& box,
                    const std::vector<PlacedSolids::Face>& faces, gp_Pnt* nearest, long& calls,
                    double stop_below = 0.0) {
  std::vector<std::pair<double, size_t>> order;
  for (size_t k = 0; k < faces.size(); ++k) order.emplace_back(box.Distance(faces[k].box), k);
  std::sort(order.begin(), order.end());
  double best = INFINITY;
  for (const auto& [gap, k] : order) {
    if (gap >= best || best <= stop_below) break;
    ++calls;
    BRepExtrema_DistShapeShape d(shape, faces[k].face);
    if (!d.IsDone() || d.NbSolution() < 1) continue;
    if (d.Value() < best) {
      best = d.Value();
      if (nearest) *nearest = d.PointOnShape2(1);
    }
  }
  return best;
}

// The distance from `p` to a solid's boundary and its nearest boundary point.
double to_boundary(const std::vector<PlacedSolids::Face>& faces, const gp_Pnt& p, gp_Pnt& nearest,
                   long& calls) {
  Bnd_Box at;
  at.Add(p);
  const double d = nearest_face(BRepBuilderAPI_MakeVertex(p).Vertex(), at, faces, &nearest, calls);
  return std::isfinite(d) ? d : 0.0;
}

// The distance between two solids' boundaries, nearest face pairs first,
// stopping once it is at most `touch` (contact: nothing nearer matters).
// Face pairs whose boxes are farther apart than `measure_within` are measured
// only while the budget of kExactFacePairs lasts; `exact` tells whether the
// result is the distance or a lower bound of it (the nearest box gap left).
struct BoundaryDistance {
  double value = INFINITY;
  bool exact = true;
  bool timed_out = false;  ///< the deadline came first: `value` is the nearest box gap left
};
BoundaryDistance boundary_distance(const PlacedSolids& a, size_t i, const PlacedSolids& b, size_t j,
                                   double touch, double measure_within, Clock::time_point deadline,
                                   long& calls) {
  struct Candidate {
    double gap;
    size_t fa, fb;
  };
  std::vector<Candidate> order;
  for (size_t x = 0; x < a.faces[i].size(); ++x)
    for (size_t y = 0; y < b.faces[j].size(); ++y)
      order.push_back({a.faces[i][x].box.Distance(b.faces[j][y].box), x, y});
  std::sort(order.begin(), order.end(),
            [](const Candidate& p, const Candidate& q) { return p.gap < q.gap; });
  BoundaryDistance out;
  long measured = 0;
  for (const Candidate& c : order) {
    if (c.gap >= out.value || out.value <= touch) break;
    if (c.gap > measure_within && measured >= tol::kExactFacePairs) {
      out.value = c.gap;  // every face pair left is at least this far apart
      out.exact = false;
      break;
    }
    // Free-form faces (gear teeth) can cost a second a pair, and close ones
    // are many: the time box holds here too.
    if (Clock::now() > deadline) {
      out.value = c.gap;
      out.exact = false;
      out.timed_out = true;
      break;
    }
    ++calls;
    ++measured;
    BRepExtrema_DistShapeShape d(a.faces[i][c.fa].face, b.faces[j][c.fb].face);
    if (d.IsDone() && d.NbSolution() > 0) out.value = std::min(out.value, d.Value());
  }
  return out;
}

// A vertex of solid `s` (a point on its boundary).
gp_Pnt some_point(const TopoDS_Solid& s) {
  TopExp_Explorer v(s, TopAbs_VERTEX);
  return BRep_Tool::Pnt(TopoDS::Vertex(v.Current()));
}

// φ(x) = min(d(x, ∂A), d(x, ∂B)) at a point verified inside both (else −1), and
// the two nearest boundary points.
struct Probe {
  double phi = -1.0, da = 0.0, db = 0.0;
  gp_Pnt pa, pb;
};
Probe probe(const PlacedSolids& a, const PlacedSolids& b, const gp_Pnt& x, ExactMeasure& m) {
  Probe out;
  const int ia = inside(a, x, m.classifications);
  if (ia < 0) return out;
  const int ib = inside(b, x, m.classifications);
  if (ib < 0) return out;
  out.da = to_boundary(a.faces[size_t(ia)], x, out.pa, m.distance_calls);
  out.db = to_boundary(b.faces[size_t(ib)], x, out.pb, m.distance_calls);
  out.phi = std::min(out.da, out.db);
  return out;
}

// The largest φ from the start points and a local ascent from the best: each
// step moves away from the nearer boundary (towards balancing both) or, when
// balanced, along both escape directions; a step that does not gain is halved.
void lower_bound(const PlacedSolids& a, const PlacedSolids& b, const std::vector<gp_Pnt>& starts,
                 Clock::time_point deadline, ExactMeasure& m) {
  Probe best;
  gp_Pnt at;
  for (const gp_Pnt& s : starts) {
    if (Clock::now() > deadline) break;
    const Probe p = probe(a, b, s, m);
    if (p.phi > best.phi) best = p, at = s;
  }
  if (best.phi < 0) return;
  double step = 0.5 * best.phi;
  for (int k = 0; k < 40 && step > 1e-9 && Clock::now() < deadline; ++k) {
    const gp_Vec ga(best.pa, at), gb(best.pb, at);  // away from each boundary
    gp_Vec move;
    const double gap = best.db - best.da;
    if (std::abs(gap) > 0.1 * best.phi && ga.Magnitude() > 0 && gb.Magnitude() > 0) {
      move = (gap > 0 ? ga.Normalized() : gb.Normalized()) * std::min(step, 0.5 * std::abs(gap));
    } else if (ga.Magnitude() > 0 && gb.Magnitude() > 0) {
      const gp_Vec both = ga.Normalized() + gb.Normalized();
      if (both.Magnitude() < 1e-9) break;  // opposite walls: the middle is reached
      move = both.Normalized() * step;
    } else {
      break;
    }
    const gp_Pnt next = at.Translated(move);
    const Probe p = probe(a, b, next, m);
    if (p.phi > best.phi) {
      best = p;
      at = next;
    } else {
      step *= 0.5;
    }
  }
  m.lower = 2.0 * best.phi;
  m.lower_at = Vec3(at.X(), at.Y(), at.Z());
}

// The width of `s` across its thinnest side, from boxes that enclose its exact
// geometry: the axis-aligned one and one in the axes of its oriented box.
double width(const TopoDS_Shape& s) {
  Bnd_Box world;
  BRepBndLib::AddOptimal(s, world, Standard_False, Standard_False);
  double x0, y0, z0, x1, y1, z1;
  world.Get(x0, y0, z0, x1, y1, z1);
  double w = std::min({x1 - x0, y1 - y0, z1 - z0});
  Bnd_OBB obb;
  BRepBndLib::AddOBB(s, obb, Standard_False, Standard_False, Standard_False);
  if (!obb.IsVoid()) {
    const gp_Ax3 frame(obb.Center(), gp_Dir(obb.ZDirection()), gp_Dir(obb.XDirection()));
    gp_Trsf into;
    into.SetTransformation(frame);  // world → the box's axes
    Bnd_Box turned;
    BRepBndLib::AddOptimal(s.Moved(TopLoc_Location(into)), turned, Standard_False, Standard_False);
    turned.Get(x0, y0, z0, x1, y1, z1);
    w = std::min({w, x1 - x0, y1 - y0, z1 - z0});
  }
  return w;
}

void common_bound(const PlacedSolids& a, const PlacedSolids& b, Clock::time_point deadline,
                  double touch, ExactMeasure& m) {
  double upper = 0.0, volume = 0.0;
  for (size_t i = 0; i < a.solids.size(); ++i)
    for (size_t j = 0; j < b.solids.size(); ++j) {
      if (a.boxes[i].IsOut(b.boxes[j])) continue;
      Handle(Deadline) stop = new Deadline(deadline);
      BRepAlgoAPI_Common c(a.solids[i], b.solids[j], stop->Start());
      if (stop->UserBreak()) {
        m.common_timed_out = true;
        return;
      }
      if (!c.IsDone() || c.HasErrors()) {
        m.common_error = "the Boolean common of the solids failed";
        return;
      }
      for (TopExp_Explorer x(c.Shape(), TopAbs_SOLID); x.More(); x.Next()) {
        GProp_GProps g;
        BRepGProp::VolumeProperties(x.Current(), g);
        if (!(g.Mass() > touch * touch * touch)) continue;  // a sliver of rounding
        volume += g.Mass();
        upper = std::max(upper, width(x.Current()));
      }
    }
  m.upper = upper;
  m.volume = volume;
}

}  // namespace

ExactMeasure occt_measure_exact_pair(const ExactPart& pa, const ExactPart& pb,
                                     const ExactRequest& r) {
  const auto t0 = Clock::now();
  const auto deadline =
      t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(r.seconds));
  ExactMeasure m;
  const double to_mm = r.mm_per_unit, to_scene = 1.0 / r.mm_per_unit;
  try {
    const PlacedSolids& a = placed_solids(pa, to_mm);
    const PlacedSolids& b = placed_solids(pb, to_mm);
    m.solids_a = int(a.solids.size());
    m.solids_b = int(b.solids.size());
    if (a.solids.empty() || b.solids.empty()) throw std::runtime_error("a part has no solid");
    // The solids' distance: their boundaries', nearest faces first; 0 where
    // one holds the other (a point of its boundary strictly inside).
    const double touch = r.touch * to_mm;
    double d = INFINITY;
    bool exact = true;
    const double measure_within = std::max(touch, r.measure_within * to_mm);
    for (size_t i = 0; i < a.solids.size(); ++i)
      for (size_t j = 0; j < b.solids.size(); ++j) {
        if (a.boxes[i].Distance(b.boxes[j]) >= d) continue;
        const BoundaryDistance bd =
            boundary_distance(a, i, b, j, touch, measure_within, deadline, m.distance_calls);
        m.distance_timed_out = m.distance_timed_out || bd.timed_out;
        double dij = bd.value;
        if (dij > touch) {
          ++m.classifications;
          BRepClass3d_SolidClassifier in_b(b.solids[j], some_point(a.solids[i]), 1e-9);
          ++m.classifications;
          BRepClass3d_SolidClassifier in_a(a.solids[i], some_point(b.solids[j]), 1e-9);
          if (in_b.State() == TopAbs_IN || in_a.State() == TopAbs_IN) dij = 0.0;
        }
        // 0 from containment is exact; 0 as a timed-out box gap is not.
        if (dij < d) d = dij, exact = bd.exact || (dij == 0.0 && dij != bd.value);
      }
    m.distance = d * to_scene;
    m.distance_exact = exact;
    if (d <= touch && !m.distance_timed_out) {
      std::vector<gp_Pnt> starts;
      for (const Vec3& s : r.starts)
        starts.emplace_back(s.x() * to_mm, s.y() * to_mm, s.z() * to_mm);
      const auto lower_deadline =
          t0 + std::chrono::duration_cast<Clock::duration>(
                   std::chrono::duration<double>(tol::kExactLowerShare * r.seconds));
      lower_bound(a, b, starts, lower_deadline, m);
      m.lower *= to_scene;
      if (m.lower_at) m.lower_at = *m.lower_at * to_scene;
      if (r.common) {
        common_bound(a, b, deadline, r.touch * to_mm, m);
        if (m.upper) m.upper = *m.upper * to_scene;
        if (m.volume) m.volume = *m.volume * to_scene * to_scene * to_scene;
      }
    }
    m.ok = true;
  } catch (const Standard_Failure& e) {
    m.error = std::string("Open CASCADE failed: ") + e.GetMessageString();
  } catch (const std::exception& e) {
    m.error = e.what();
  }
  m.seconds = since(t0);
  return m;
}

}  // namespace pd
