#include "solve/certificate.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>

#include "tolerances.h"

namespace pd {

namespace {

// The point of face f (0..5: ±x, ±y, ±z) at face coordinates (s, t) in [−1, 1]².
Vec3 cube_point(int f, double s, double t) {
  const double sign = f % 2 ? -1.0 : 1.0;
  switch (f / 2) {
    case 0:
      return Vec3(sign, s, t).normalized();
    case 1:
      return Vec3(t, sign, s).normalized();
    default:
      return Vec3(s, t, sign).normalized();
  }
}

}  // namespace

const std::vector<SphereCell>& cube_sphere_cells(int n) {
  static std::map<int, std::vector<SphereCell>> cache;
  static std::mutex lock;
  std::lock_guard<std::mutex> g(lock);
  auto& cells = cache[n];
  if (!cells.empty()) return cells;
  for (int f = 0; f < 6; ++f) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double s0 = -1 + 2.0 * i / n, s1 = -1 + 2.0 * (i + 1) / n;
        const double t0 = -1 + 2.0 * j / n, t1 = -1 + 2.0 * (j + 1) / n;
        const Vec3 c = cube_point(f, 0.5 * (s0 + s1), 0.5 * (t0 + t1));
        // A projected square is a convex spherical quadrilateral: the point
        // farthest from its centre is a corner.
        const std::array<Vec3, 4> corners{cube_point(f, s0, t0), cube_point(f, s1, t0),
                                          cube_point(f, s1, t1), cube_point(f, s0, t1)};
        double r = 0;
        for (const Vec3& k : corners) r = std::max(r, angle_between(c, k));
        cells.push_back({c, r * (1 + tol::kCellRadiusPad), corners, f, i, j});
      }
    }
  }
  return cells;
}

CellSupports cell_supports(const PairProblem& pr, int grid) {
  const auto& cells = cube_sphere_cells(grid);
  const size_t nc = cells.size();
  CellSupports s;
  s.x.resize(nc);
  s.g.resize(nc);
  thread_local std::vector<Vec3> centres;
  thread_local std::vector<double> hp, hq;
  thread_local std::vector<Eigen::Index> ip, iq;
  centres.resize(nc);
  hp.resize(nc);
  hq.resize(nc);
  ip.resize(nc);
  iq.resize(nc);
  for (size_t k = 0; k < nc; ++k) centres[k] = cells[k].centre;
  pr.p_soa().max_dots(centres.data(), nc, 1.0, hp.data(), ip.data());
  pr.q_soa().max_dots(centres.data(), nc, -1.0, hq.data(), iq.data());  // −min_j q_j·c
  for (size_t k = 0; k < nc; ++k) {
    s.x[k] = pr.p().col(ip[k]) - pr.q().col(iq[k]);
    s.g[k] = hp[k] - -hq[k];  // max − min, as max_dot − min_dot
  }
  return s;
}

CapCover open_region_caps(const PairProblem& pr, double best, int grid, double max_radius,
                          int max_caps) {
  CapCover out = open_region_caps(cell_supports(pr, grid), best, grid, max_radius, max_caps);
  out.evaluations = static_cast<long>(cube_sphere_cells(grid).size());
  return out;
}

CapCover open_region_caps(const CellSupports& s, double best, int grid, double max_radius,
                          int max_caps) {
  const auto& cells = cube_sphere_cells(grid);
  const size_t nc = cells.size();
  CapCover out;
  const std::vector<Vec3>& x = s.x;
  const std::vector<double>& g = s.g;
  // The smallest of x·corner; exact on the cell when all are positive (see the
  // header), and then only rounding separates it from the true minimum.
  auto bound = [&](size_t cell, size_t from) {
    double lo = std::numeric_limits<double>::infinity();
    for (const Vec3& k : cells[cell].corners) lo = std::min(lo, x[from].dot(k));
    return lo > 0 ? lo : -1.0;
  };
  // Open cells: no support point of the cell or of its neighbours on the same
  // face lifts the gap above `best` everywhere on the cell.
  const double threshold = best + 1e-12 * std::max(1.0, std::abs(best));
  std::vector<size_t> open;
  for (size_t k = 0; k < nc; ++k) {
    const SphereCell& c = cells[k];
    bool closed = bound(k, k) > threshold;
    for (int di = -1; di <= 1 && !closed; ++di) {
      for (int dj = -1; dj <= 1 && !closed; ++dj) {
        const int i = c.i + di, j = c.j + dj;
        if (i < 0 || j < 0 || i >= grid || j >= grid) continue;
        closed = bound(k, size_t(c.face) * grid * grid + size_t(i) * grid + size_t(j)) > threshold;
      }
    }
    if (!closed) open.push_back(k);
  }
  // Fail fast: a cap of max_radius holds at most its area over the smallest
  // cell's (a gnomonic cell is >= kMinCellAreaFraction of the mean area at any grid), so more
  // open cells than max_caps such caps can hold cannot be covered.
  const double cap_area = 2 * M_PI * (1 - std::cos(max_radius));
  const double min_cell = tol::kMinCellAreaFraction * 4 * M_PI / double(nc);
  if (double(open.size()) > max_caps * cap_area / min_cell) {
    out.ok = false;
    return out;
  }
  // Connected groups of open cells (cells whose caps touch), one cap each,
  // centred on the group's mean direction; a group too wide for one cap is
  // covered greedily from its lowest cell.
  std::vector<int> group(open.size());
  std::iota(group.begin(), group.end(), 0);
  std::function<int(int)> root = [&](int k) {
    return group[k] == k ? k : group[k] = root(group[k]);
  };
  for (size_t u = 0; u < open.size(); ++u)
    for (size_t w = u + 1; w < open.size(); ++w) {
      const SphereCell &cu = cells[open[u]], &cw = cells[open[w]];
      if (angle_between(cu.centre, cw.centre) <= tol::kCellJoinSlack * (cu.radius + cw.radius))
        group[root(int(u))] = root(int(w));
    }
  std::map<int, std::vector<size_t>> groups;
  for (size_t u = 0; u < open.size(); ++u) groups[root(int(u))].push_back(open[u]);
  auto need = [&](const Vec3& centre, size_t cell) {
    return angle_between(centre, cells[cell].centre) + cells[cell].radius;
  };
  for (auto& [id, members] : groups) {
    Vec3 mean = Vec3::Zero();
    for (size_t c : members) mean += cells[c].centre;
    if (mean.norm() > 1e-9) {
      mean.normalize();
      double radius = 0;
      for (size_t c : members) radius = std::max(radius, need(mean, c));
      if (radius <= max_radius) {
        out.caps.emplace_back(mean, radius);
        continue;
      }
    }
    std::sort(members.begin(), members.end(), [&](size_t a, size_t b) { return g[a] < g[b]; });
    std::vector<char> covered(members.size(), 0);
    for (size_t first = 0; first < members.size(); ++first) {
      if (covered[first]) continue;
      const Vec3 centre = cells[members[first]].centre;
      double radius = 0;
      for (size_t k = first; k < members.size(); ++k)
        if (!covered[k] && need(centre, members[k]) <= max_radius) {
          covered[k] = 1;
          radius = std::max(radius, need(centre, members[k]));
        }
      out.caps.emplace_back(centre, radius);
    }
  }
  if (static_cast<int>(out.caps.size()) > max_caps) out.ok = false;
  return out;
}

}  // namespace pd
