#include "solve/certificate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

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
        double r = 0;
        for (double s : {s0, s1})
          for (double t : {t0, t1}) r = std::max(r, angle_between(c, cube_point(f, s, t)));
        cells.push_back({c, r * (1 + 1e-9), f, i, j});
      }
    }
  }
  return cells;
}

CapCover open_region_caps(const PairProblem& pr, double best, const Vec3& best_v, int grid,
                          double max_radius, int max_caps) {
  const auto& cells = cube_sphere_cells(grid);
  const size_t nc = cells.size();
  CapCover out;
  // Support points and gaps at the cell centres.
  std::vector<Vec3> x(nc);
  std::vector<double> g(nc);
  for (size_t k = 0; k < nc; ++k) {
    const Vec3& c = cells[k].centre;
    Eigen::Index ip = 0, iq = 0;
    const double hp = (c.transpose() * pr.p()).maxCoeff(&ip);
    const double hq = (c.transpose() * pr.q()).minCoeff(&iq);
    x[k] = pr.p().col(ip) - pr.q().col(iq);
    g[k] = hp - hq;
  }
  out.evaluations = static_cast<long>(nc);
  auto bound = [&](size_t cell, size_t from) {
    const double nx = x[from].norm();
    if (nx == 0) return 0.0;
    const double a = angle_between(x[from] / nx, cells[cell].centre) + cells[cell].radius;
    return a >= M_PI ? -nx : nx * std::cos(a);
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
  // Greedy caps: first at the best direction, then at the lowest open cell left.
  std::sort(open.begin(), open.end(), [&](size_t a, size_t b) { return g[a] < g[b]; });
  std::vector<char> covered(open.size(), 0);
  size_t left = open.size();
  Vec3 centre = best_v;
  while (left > 0) {
    if (static_cast<int>(out.caps.size()) >= max_caps) {
      out.ok = false;
      return out;
    }
    double radius = 0;
    for (size_t k = 0; k < open.size(); ++k) {
      if (covered[k]) continue;
      const double need = angle_between(centre, cells[open[k]].centre) + cells[open[k]].radius;
      if (need <= max_radius) {
        covered[k] = 1;
        --left;
        radius = std::max(radius, need);
      }
    }
    if (radius > 0) {
      out.caps.emplace_back(centre, radius);
    } else if (centre != best_v) {
      out.ok = false;  // a cell wider than max_radius: the grid is too coarse
      return out;
    }
    for (size_t k = 0; k < open.size(); ++k)
      if (!covered[k]) {
        centre = cells[open[k]].centre;
        break;
      }
  }
  return out;
}

}  // namespace pd
