// A hand-made run for the report writers' in-process tests: parts and pair
// results set field by field, the context and review options a CLI run would
// give them, and the run's review. No scene, no solver, no binary.
#pragma once

#include <array>
#include <string>

#include "report/report_json.h"
#include "report/review.h"
#include "report/writer.h"

namespace pd::test {

struct ReportFixture {
  RunResult run;
  ReportContext context;
  ReviewOptions options;
  Review review;

  explicit ReportFixture(const std::string& units = "mm", double tolerance = 0.1) {
    context.scene_path = "scene.json";
    context.units = units;
    context.tolerance = tolerance;
    options.tolerance = tolerance;
    options.units = units;
  }

  /// A usable inline part, its box [3k, 3k + 4] x [0, 1] x [0, 1] (k: its index).
  Part& part(const std::string& id) {
    Part p;
    p.id = id;
    p.source = "inline";
    const double x = 3.0 * static_cast<double>(run.parts.size());
    p.box = {Vec3(x, 0, 0), Vec3(x + 4, 1, 1)};
    run.parts.push_back(p);
    run.all_pairs = static_cast<long>(run.parts.size() * (run.parts.size() - 1) / 2);
    return run.parts.back();
  }

  /// A pair result of parts a and b: `depth` against the context's tolerance,
  /// an error message for kError.
  PairResult& pair(int a, int b, Status status, double depth) {
    PairResult r;
    r.a = a;
    r.b = b;
    r.status = status;
    r.depth = depth;
    r.margin = context.tolerance - depth;
    r.method = "exact";
    if (status == Status::kError) r.error = "worker crashed, signal 11";
    run.pairs.push_back(r);
    return run.pairs.back();
  }

  /// Reviews the run as it stands (incomplete as its summary says) and
  /// returns what a writer is given. Call again after changing the run.
  ReportInput input() {
    review = review_run(run, options, summarize(run).incomplete());
    return {context, run, review, options};
  }
};

/// Every kind of entry a writer shows, in mm with tolerance 0.1: parts frame,
/// "lid <&>", pin, bolt and bad (failed to load); an interference frame / lid
/// 1.0 deep (moving the lid up clears it), a false positive frame / pin, a
/// separated pair frame / bolt, an interference lid / pin 0.3 deep (moving the
/// lid up clears it too: one finding group with the first), an undecided pair
/// lid / bolt and a failed one pin / bolt.
inline ReportFixture every_status() {
  ReportFixture f;
  for (const char* id : {"frame", "lid <&>", "pin", "bolt", "bad"}) f.part(id);
  f.run.parts[4].error = "unreadable: no such file";
  f.run.simulated = {"interference"};
  f.pair(0, 1, Status::kInterference, 1.0).direction = Vec3::UnitZ();
  f.pair(0, 2, Status::kFalsePositive, 0.05);
  f.pair(0, 3, Status::kSeparated, 0.0).distance = 2.0;
  f.pair(1, 2, Status::kInterference, 0.3).direction = -Vec3::UnitZ();
  PairResult& u = f.pair(1, 3, Status::kUndecided, 0.1);
  u.depth_bounds = std::array<double, 2>{0.05, 0.2};
  u.reason = "work box exhausted";
  f.pair(2, 3, Status::kError, 0.0);
  f.run.unchecked = 4;  // the bad part's pairs
  return f;
}

}  // namespace pd::test
