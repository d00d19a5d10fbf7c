// lowest_local_facet: the lowest facet of a local Minkowski difference inside a
// cap, found from facet-normal candidates (no hull) on small sets, against the
// facets of qhull's hull of every difference.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "corpus/generators.h"
#include "geometry/hull.h"
#include "solve/neighbourhood.h"

using namespace pd;

namespace {

std::vector<int> all(Eigen::Index n) {
  std::vector<int> ids(static_cast<size_t>(n));
  std::iota(ids.begin(), ids.end(), 0);
  return ids;
}

// Points on a few planes and lines as well as in general position: coplanar
// faces and parallel edges are where a facet is easy to miss.
Points cloud(SphereSampler& r, int n, int kind) {
  Points x(3, n);
  for (int k = 0; k < n; ++k) {
    x.col(k) = r.direction() * (0.5 + r.uniform());
    if (kind == 1) x(2, k) = k % 2 ? 0.3 : -0.3;           // two parallel planes: a prism
    if (kind == 2) x(2, k) = std::round(x(2, k) * 2) / 2;  // a few levels
  }
  return x;
}

}  // namespace

TEST(Neighbourhood, CandidateFacetsNeverMissAFacetOfTheHullInTheCap) {
  SphereSampler r(5);
  int compared = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const int a = 1 + trial % 5, b = 1 + (trial / 5) % 5;  // small: the path without a hull
    const Points p = cloud(r, a, trial % 3), q = cloud(r, b, (trial / 3) % 3);
    const Vec3 v = r.direction();
    const double radius = 0.05 + 0.6 * r.uniform();
    Points m(3, a * b);
    for (int i = 0; i < a; ++i)
      for (int j = 0; j < b; ++j) m.col(i * b + j) = p.col(i) - q.col(j);
    HullFacets f;
    if (m.cols() < 4 || !hull_facets(m, f)) continue;  // flat or smaller: no reference here
    double reference = INFINITY;
    for (size_t t = 0; t < f.normals.size(); ++t)
      if (f.normals[t].dot(v) >= std::cos(radius)) reference = std::min(reference, -f.offsets[t]);
    const auto got = lowest_local_facet(p, q, all(a), all(b), v, radius);
    SCOPED_TRACE("trial " + std::to_string(trial));
    if (std::isfinite(reference)) {
      ASSERT_TRUE(got.has_value());
      ++compared;
      // Every facet normal is a candidate and a facet is kept: the same lowest facet.
      EXPECT_NEAR(got->offset, reference, 1e-12);
    }
    if (got) {
      // Whatever is returned is a direction in the cap, valued exactly.
      EXPECT_NEAR(got->normal.norm(), 1.0, 1e-15);
      EXPECT_GE(got->normal.dot(v), std::cos(radius) - 1e-15);
      EXPECT_NEAR(got->offset, (got->normal.transpose() * m).maxCoeff(), 1e-14);
    }
  }
  EXPECT_GT(compared, 200);  // the caps held facets often enough to mean something
}
