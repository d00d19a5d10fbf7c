// The one description of a pair result's fields: key, order and how the report
// shows each (results/field.h). The codec (results/codec.h) walks it to write
// and to read both encodings, so a field added to PairResult is one line here.
//
// Each for_each_field calls `visit(Field, member)` for every field in report
// order, on a const object (writing) or a mutable one (reading). The pair's
// identity (a, b) is the codec's own: indices in the complete encoding, ids
// and the fingerprint in the report.
#pragma once

#include <type_traits>

#include "results/field.h"
#include "results/pair_result.h"

namespace pd {

/// void for T and const T alone: each for_each_field takes its own type.
template <class Self, class T>
using IfFieldsOf = std::enable_if_t<std::is_same_v<std::remove_const_t<Self>, T>>;

template <class S, class Visit>
auto for_each_field(S& s, Visit&& visit) -> IfFieldsOf<S, SolveStats> {
  visit(Field{"local_solves"}, s.local_solves);
  visit(Field{"distinct_optima"}, s.distinct_optima);
  visit(Field{"alpha_evaluations"}, s.alpha_evaluations);
  visit(Field{"ipopt_calls"}, s.ipopt_calls);
  visit(Field{"ipopt_iterations"}, s.ipopt_iterations);
  visit(Field{"ipopt_failures"}, s.ipopt_failures);
  visit(Field{"stop_reason"}, s.stop_reason);
  visit(Field{"mlsl_iterations"}.when(false), s.mlsl_iterations);  // not in the report
}

template <class M, class Visit>
auto for_each_field(M& m, Visit&& visit) -> IfFieldsOf<M, MotionTrace> {
  visit(Field{"steps"}, m.steps);
  visit(Field{"max_depth"}, m.max_depth);
  visit(Field{"t_max_depth"}, m.t_max_depth);
  visit(Field{"min_distance"}, m.min_distance);
  visit(Field{"t_min_distance"}.when(m.min_distance.has_value()), m.t_min_distance);
  visit(Field{"series"}.unless_empty(), m.series);
}

template <class E, class Visit>
auto for_each_field(E& e, Visit&& visit) -> IfFieldsOf<E, ExactCheck> {
  visit(Field{"verdict"}, e.verdict);
  visit(Field{"by"}.when(decisive(e.verdict)), e.basis);
  visit(Field{"distance"}, e.distance);
  visit(Field{"depth_bounds"}, e.depth_bounds);
  visit(Field{"volume"}, e.volume);
  visit(Field{"seconds"}, e.seconds);
  visit(Field{"reason"}.unless_empty(), e.reason);
}

template <class R, class Visit>
auto for_each_field(R& r, Visit&& visit) -> IfFieldsOf<R, PairResult> {
  visit(Field{"status"}, r.status);
  visit(Field{"duplicate"}.unless_empty(), r.duplicate);
  // tolerance auto: the pair's own band and what it rests on (absent otherwise).
  visit(Field{"tolerance"}, r.tolerance);
  visit(Field{"tolerance_source"}.unless_empty(), r.tolerance_source);
  visit(Field{"tolerance_basis"}.unless_empty(), r.tolerance_basis);
  // Rules (docs/scene-format.md): the tests covering the pair, its expected contact.
  visit(Field{"tests"}.unless_empty(), r.tests);
  visit(Field{"expected"}.unless_empty(), r.expected);
  // The report gives an error pair its error alone, a decided pair its answer.
  const bool decided = r.status != Status::kError;
  visit(Field{"error"}.when(!decided), r.error);
  visit(Field{"depth"}.when(decided), r.depth);
  visit(Field{"direction"}.when(decided), r.direction);
  visit(Field{"margin"}.when(decided), r.margin);
  visit(Field{"distance"}.when(decided), r.distance);
  visit(Field{"depth_source"}.when(decided), r.depth_source);
  visit(Field{"hull_depth"}.when(decided), r.hull_depth);
  visit(Field{"depth_bounds"}.when(decided), r.depth_bounds);
  visit(Field{"confirmed"}.when(decided), r.confirmed);
  visit(Field{"pieces"}.when(decided), r.pieces);
  visit(Field{"at"}.when(decided), r.at);
  visit(Field{"reason"}.when(decided).unless_empty(), r.reason);
  visit(Field{"min"}.in("clearance").when(decided), r.clearance_min);
  visit(Field{"distance"}.in("clearance").when(decided && r.clearance_min).echoing(), r.distance);
  visit(Field{"gap_band"}.in("clearance").when(decided), r.gap_band);
  visit(Field{"gap_basis"}.in("clearance").when(decided).unless_empty(), r.gap_basis);
  visit(Field{"motion"}.when(decided), r.motion);
  visit(Field{"exact"}, r.exact);
  visit(Field{"method"}, r.method);
  visit(Field{"fallback"}.unless_empty(), r.fallback);
  visit(Field{"warnings"}.unless_empty(), r.warnings);
  visit(Field{"stats"}, r.stats);
  visit(Field{"time_ms"}, r.time_ms);
  visit(Field{"reused"}.unless_empty(), r.reused);
}

}  // namespace pd
