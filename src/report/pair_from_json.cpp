#include "report/pair_from_json.h"

namespace pd {

Status status_from_name(const std::string& name) {
  for (Status s : {Status::kSeparated, Status::kFalsePositive, Status::kInterference,
                   Status::kError, Status::kClearanceViolation, Status::kUndecided})
    if (name == status_name(s)) return s;
  throw std::invalid_argument("unknown status \"" + name + "\"");
}

namespace {

StopReason stop_reason_from_name(const std::string& name) {
  for (StopReason r : {StopReason::kNone, StopReason::kProvenSeparated, StopReason::kContact,
                       StopReason::kCertificate, StopReason::kBayesian, StopReason::kCap})
    if (name == stop_reason_name(r)) return r;
  throw std::invalid_argument("unknown stop_reason \"" + name + "\"");
}

}  // namespace

PairResult pair_from_json(const nlohmann::ordered_json& j, int a, int b) {
  PairResult r;
  r.a = a;
  r.b = b;
  r.status = status_from_name(j.at("status").get<std::string>());
  if (r.status == Status::kError) {
    r.error = j.at("error").get<std::string>();
  } else {
    r.depth = j.at("depth").get<double>();
    const auto& d = j.at("direction");
    r.direction = Vec3(d.at(0).get<double>(), d.at(1).get<double>(), d.at(2).get<double>());
    r.margin = j.at("margin").get<double>();
    if (j.contains("distance")) r.distance = j["distance"].get<double>();
    r.depth_source = j.at("depth_source").get<std::string>();
    if (j.contains("hull_depth")) r.hull_depth = j["hull_depth"].get<double>();
    if (j.contains("depth_bounds")) r.depth_bounds = j["depth_bounds"].get<std::array<double, 2>>();
    if (j.contains("confirmed")) r.confirmed = j["confirmed"].get<bool>();
    if (j.contains("pieces")) r.pieces = j["pieces"].get<std::array<int, 2>>();
    if (j.contains("at")) {
      const auto& p = j["at"];
      r.at = Vec3(p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>());
    }
    if (j.contains("reason")) r.reason = j["reason"].get<std::string>();
    if (j.contains("clearance")) r.clearance_min = j["clearance"].at("min").get<double>();
    if (j.contains("motion")) {
      const auto& mo = j["motion"];
      MotionTrace m;
      m.steps = mo.at("steps").get<long>();
      m.max_depth = mo.at("max_depth").get<double>();
      m.t_max_depth = mo.at("t_max_depth").get<double>();
      if (mo.contains("min_distance")) {
        m.min_distance = mo["min_distance"].get<double>();
        m.t_min_distance = mo.at("t_min_distance").get<double>();
      }
      if (mo.contains("series"))
        for (const auto& p : mo["series"])
          m.series.emplace_back(p.at(0).get<double>(), p.at(1).get<double>());
      r.motion = m;
    }
  }
  r.method = j.at("method").get<std::string>();
  if (j.contains("fallback")) r.fallback = j["fallback"].get<std::string>();
  if (j.contains("warnings")) r.warnings = j["warnings"].get<std::vector<std::string>>();
  const auto& st = j.at("stats");
  r.stats.local_solves = st.at("local_solves").get<int>();
  r.stats.distinct_optima = st.at("distinct_optima").get<int>();
  r.stats.alpha_evaluations = st.at("alpha_evaluations").get<long>();
  r.stats.ipopt_calls = st.at("ipopt_calls").get<decltype(r.stats.ipopt_calls)>();
  r.stats.ipopt_iterations = st.at("ipopt_iterations").get<decltype(r.stats.ipopt_iterations)>();
  r.stats.ipopt_failures = st.at("ipopt_failures").get<decltype(r.stats.ipopt_failures)>();
  r.stats.stop_reason = stop_reason_from_name(st.at("stop_reason").get<std::string>());
  r.time_ms = j.at("time_ms").get<double>();
  return r;
}

}  // namespace pd
