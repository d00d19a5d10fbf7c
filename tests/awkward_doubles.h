// Every double a pair's result may hold, the awkward ones included (issue 11),
// and a pair result holding one of them in every double field: the codec's
// and the worker pipe's bit-for-bit tests (test_codec, test_run).
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>

#include "results/pair_result.h"

namespace pd_test {

inline std::uint64_t raw_bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

inline double from_bits(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

inline const double kAwkward[] = {std::numeric_limits<double>::quiet_NaN(),
                                  -std::numeric_limits<double>::quiet_NaN(),
                                  from_bits(0x7ff4000000000123ULL),  // a NaN with a payload
                                  std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity(),
                                  -0.0,
                                  0.0,
                                  std::numeric_limits<double>::denorm_min(),
                                  std::numeric_limits<double>::max(),
                                  -std::numeric_limits<double>::lowest(),
                                  0.1,
                                  1.0 / 3.0,
                                  1e-300};

inline pd::PairResult with_every_double(double x) {
  pd::PairResult r;
  r.a = 3;
  r.b = 7;
  r.status = pd::Status::kInterference;
  r.depth = x;
  r.direction = pd::Vec3(x, -x, 0.5);
  r.distance = x;
  r.margin = x;
  r.method = "mlsl";
  r.time_ms = x;
  r.fallback = "f";
  r.error = "e";
  r.clearance_min = x;
  pd::MotionTrace m;
  m.steps = 5;
  m.max_depth = x;
  m.t_max_depth = x;
  m.min_distance = x;
  m.t_min_distance = x;
  m.series = {{x, x}, {1.0, x}};
  r.motion = m;
  r.warnings = {"first", "second"};
  return r;
}

}  // namespace pd_test
