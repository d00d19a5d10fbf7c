// Hand-built runs for the review's tests (baseline, suppressions, --fail-on):
// parts p0 … p5 (p5 failed to load), pairs of any status, baseline files.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "batch/run_result.h"
#include "report/input_error.h"

namespace pd::test {

inline Part part(const std::string& id, std::optional<std::string> error = std::nullopt) {
  Part p;
  p.id = id;
  p.source = "inline";
  p.error = error;
  return p;
}

inline PairResult pair(int a, int b, Status s, double depth = 0.0) {
  PairResult r;
  r.a = a;
  r.b = b;
  r.status = s;
  r.depth = depth;
  if (s == Status::kError) r.error = "worker crashed";
  return r;
}

// Parts p0 … p5; p5 failed to load.
inline RunResult run_with(std::vector<PairResult> pairs) {
  RunResult r;
  for (int k = 0; k < 5; ++k) r.parts.push_back(part("p" + std::to_string(k)));
  r.parts.push_back(part("p5", "unreadable"));
  r.pairs = std::move(pairs);
  r.simulated = {"interference"};
  return r;
}

inline std::string baseline_text(const std::string& pairs) {
  return R"({"tool": {"name": "pdcheck"}, "pairs": [)" + pairs + "]}";
}

inline std::string finding(const std::string& a, const std::string& b, const std::string& status,
                           double depth) {
  return R"({"a": ")" + a + R"(", "b": ")" + b + R"(", "status": ")" + status + R"(", "depth": )" +
         std::to_string(depth) + "}";
}

inline std::string input_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ReportInputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace pd::test
