// The one description of a part result's fields (results/part_result.h): key,
// order and how the report shows each (results/field.h), for the codec
// (results/codec.h) to write and read.
#pragma once

#include "results/field.h"
#include "results/pair_fields.h"
#include "results/part_result.h"

namespace pd {

template <class P, class Visit>
auto for_each_field(P& p, Visit&& visit) -> IfFieldsOf<P, PartResult> {
  visit(Field{"id"}, p.id);
  visit(Field{"source"}, p.source);
  visit(Field{"vertices"}, p.vertices);
  visit(Field{"hull_vertices"}, p.hull_vertices);
  visit(Field{"pieces"}, p.pieces);
  visit(Field{"warnings"}, p.warnings);
  visit(Field{"resolution"}, p.resolution);
  visit(Field{"min"}.in("box"), p.box_min);
  visit(Field{"max"}.in("box"), p.box_max);
  visit(Field{"content_hash"}.unless_empty(), p.content_hash);
  visit(Field{"convex"}, p.convex);
  visit(Field{"concave"}.in("sag"), p.sag_concave);
  visit(Field{"convex"}.in("sag"), p.sag_convex);
  visit(Field{"declared"}.in("sag"), p.sag_declared);
  visit(Field{"deflection"}.in("tessellation"), p.tessellation_deflection);
  visit(Field{"sag"}.in("tessellation"), p.tessellation_sag);
  visit(Field{"basis"}.in("tessellation").unless_empty(), p.tessellation_basis);
  visit(Field{"decomposition_seconds"}, p.decomposition_seconds);
  visit(Field{"cached"}, p.cached);
  visit(Field{"decomposition_note"}.unless_empty(), p.decomposition_note);
  visit(Field{"tags"}.unless_empty(), p.tags);
  visit(Field{"group"}.unless_empty(), p.group);
  visit(Field{"sets"}, p.sets);
  visit(Field{"error"}, p.error);
}

}  // namespace pd
