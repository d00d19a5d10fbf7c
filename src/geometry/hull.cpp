#include "geometry/hull.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/frame.h"
#include "geometry/qhull_session.h"
#include "tolerances.h"

namespace pd {

QhullSession::QhullSession(int dim, std::vector<double> coords, const char* options)
    : coords_(std::move(coords)) {
  char* buffer = nullptr;
  size_t size = 0;
  FILE* err = open_memstream(&buffer, &size);  // qhull reports errors as text
  qh_zero(&qh_, err);
  const int n = static_cast<int>(coords_.size()) / dim;
  exit_code_ =
      qh_new_qhull(&qh_, dim, n, coords_.data(), False, const_cast<char*>(options), nullptr, err);
  fclose(err);
  if (buffer) {
    if (exit_code_ != 0) error_.assign(buffer, size);
    free(buffer);
  }
}

QhullSession::~QhullSession() {
  int curlong = 0, totlong = 0;
  qh_freeqhull(&qh_, !qh_ALL);
  qh_memfreeshort(&qh_, &curlong, &totlong);
}

std::vector<int> QhullSession::vertex_ids() {
  qhT* qh = &qh_;
  std::vector<int> ids;
  vertexT* vertex;
  FORALLvertices {
    ids.push_back(qh_pointid(qh, vertex->point));
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

namespace {

std::vector<double> interleave(const Points& p, const Eigen::MatrixXd& basis) {
  // Project onto the columns of `basis` (3 × d) and store point after point.
  const Eigen::MatrixXd proj = basis.transpose() * p;
  return std::vector<double>(proj.data(), proj.data() + proj.size());
}

// The input indices of a triangulated ("Qt") facet's three corners.
std::array<int, 3> facet_corners(qhT* qh, facetT* facet) {
  std::array<int, 3> tri{0, 0, 0};
  int k = 0;
  vertexT *vertex, **vertexp;
  FOREACHvertex_(facet->vertices) {
    if (k < 3) tri[k] = qh_pointid(qh, vertex->point);
    ++k;
  }
  return tri;
}

Points select(const Points& p, const std::vector<int>& ids) {
  Points out(3, ids.size());
  for (size_t k = 0; k < ids.size(); ++k) out.col(k) = p.col(ids[k]);
  return out;
}

}  // namespace

Hull convex_hull(const Points& pts) {
  return convex_hull(pts, nullptr);
}

namespace {

// A point set centred in its frame, its principal axes and how many of them
// it spans (3 solid, 2 flat, 1 collinear, 0 a point): robust to scale.
struct Spread {
  Points c;
  Eigen::Matrix3d axes;
  int dim = 3;
};

Spread spread_of(const Points& pts) {
  if (pts.cols() == 0) throw std::invalid_argument("no vertices");
  if (!pts.allFinite()) throw std::invalid_argument("non-finite (NaN or Inf) coordinates");
  // Principal axes of the centred, scaled set decide the dimension robustly.
  const Frame f = points_frame(pts);
  // Beyond the double range the frame cannot shrink the set to the unit ball:
  // every point would land on the centre and the part pass for a single point.
  if (!std::isfinite(f.scale))
    throw std::invalid_argument(
        "coordinates too large for double-precision arithmetic: the part's bounding box "
        "half-diagonal exceeds 1.8e308");
  Spread s;
  const Points local = f.to_local(pts);
  const Vec3 mean = local.rowwise().mean();
  s.c = local.colwise() - mean;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(s.c * s.c.transpose());
  s.axes = eig.eigenvectors();  // ascending eigenvalues
  Vec3 extent;
  for (int k = 0; k < 3; ++k) {
    const auto proj = s.axes.col(k).transpose() * s.c;
    extent[k] = proj.maxCoeff() - proj.minCoeff();
  }
  const double size = std::max(extent[2], 1e-300);
  if (extent[2] <= tol::kFlat)
    s.dim = 0;
  else if (extent[1] <= tol::kFlat * size)
    s.dim = 1;
  else if (extent[0] <= tol::kFlat * size)
    s.dim = 2;
  return s;
}

}  // namespace

Hull hull_of_hull_vertices(const Points& pts) {
  if (pts.cols() < 4 || spread_of(pts).dim != 3) return convex_hull(pts);
  Hull h;
  h.vertices = pts;
  return h;
}

Hull convex_hull(const Points& pts, HullTriangles* facets) {
  if (facets) *facets = HullTriangles{};
  Hull h;
  const Spread spread = spread_of(pts);
  const Points& c = spread.c;
  const Eigen::Matrix3d& axes = spread.axes;
  int dim = spread.dim;

  if (dim == 3) {
    // Triangulated output ("Qt") changes no vertex, only how facets are listed.
    QhullSession s(3, interleave(c, Eigen::Matrix3d::Identity()), "qhull Qt");
    if (s.ok()) {
      const std::vector<int> ids = s.vertex_ids();
      h.vertices = select(pts, ids);
      h.dimension = 3;
      if (facets) {  // c is pts moved and scaled alike: the normals hold for pts
        qhT* qh = s.qh();
        facetT* facet;
        FORALLfacets {
          std::array<int, 3> tri = facet_corners(qh, facet);
          for (int& id : tri)  // the input's index to the hull's
            id = static_cast<int>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin());
          facets->triangles.push_back(tri);
          facets->normals.emplace_back(facet->normal[0], facet->normal[1], facet->normal[2]);
        }
      }
      return h;
    }
    // Nearly flat beyond qhull's precision: fall back to the 2-D hull of the
    // projection, which keeps every extreme point's original coordinates.
    h.warnings.push_back("nearly flat point set; hulled in its plane");
    dim = 2;
  }
  h.dimension = dim;
  if (dim == 2) {
    QhullSession s(2, interleave(c, axes.rightCols(2)), "qhull");
    if (!s.ok()) throw std::runtime_error("qhull failed on a flat point set: " + s.error());
    h.vertices = select(pts, s.vertex_ids());
    h.warnings.push_back("flat part (zero thickness): its hull is a polygon of " +
                         std::to_string(h.vertices.cols()) + " vertices");
  } else if (dim == 1) {
    const Eigen::RowVectorXd proj = axes.col(2).transpose() * c;
    Eigen::Index lo = 0, hi = 0;
    proj.minCoeff(&lo);
    proj.maxCoeff(&hi);
    h.vertices = select(pts, {static_cast<int>(lo), static_cast<int>(hi)});
    h.warnings.push_back("collinear points: the part is a segment");
  } else if (dim == 0) {
    h.vertices = pts.col(0);
    h.warnings.push_back("all vertices coincide: the part is a single point");
  }
  return h;
}

bool hull_facets(const Points& pts, HullFacets& out) {
  out = HullFacets{};
  std::vector<double> coords(pts.data(), pts.data() + pts.size());
  QhullSession s(3, std::move(coords), "qhull Qt");
  if (!s.ok()) return false;
  qhT* qh = s.qh();
  facetT* facet;
  FORALLfacets {
    out.normals.emplace_back(facet->normal[0], facet->normal[1], facet->normal[2]);
    out.offsets.push_back(facet->offset);
    out.triangles.push_back(facet_corners(qh, facet));
  }
  return true;
}

}  // namespace pd
