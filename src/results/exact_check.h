// What became of a B-rep pair's verdict on the exact solids (docs/solver.md,
// "B-rep parts"; report field `exact`).
#pragma once

#include <array>
#include <optional>
#include <string>

namespace pd {

/// The exact verdict. kInterference, kFalsePositive, kTouching and kSeparated
/// are decisive: the solids' overlap thickness is bracketed above the
/// tolerance, at or below it, exactly 0 with the solids meeting, or they are
/// apart. kInconsistent: the solids' answer contradicts the mesh bracket beyond
/// the sags (the mesh verdict stands); kFailed, kTimeout: no answer (the mesh
/// verdict stands, `reason` says why); kSkipped: not measured (a part is no
/// B-rep). Appended only: the worker encoding stores the value.
enum class ExactVerdict {
  kSkipped,
  kInterference,
  kFalsePositive,
  kTouching,
  kSeparated,
  kInconsistent,
  kFailed,
  kTimeout
};
const char* exact_verdict_name(ExactVerdict v);
/// The verdict of a report name (throws std::invalid_argument for an unknown one).
ExactVerdict exact_verdict_from_name(const std::string& name);
inline bool decisive(ExactVerdict v) {
  return v == ExactVerdict::kInterference || v == ExactVerdict::kFalsePositive ||
         v == ExactVerdict::kTouching || v == ExactVerdict::kSeparated;
}

/// What a decisive verdict rests on: kBound, the mesh bracket widened by both
/// parts' certified sags ("certified by the deflection bound", no solid
/// touched); kSolids, Open CASCADE's measurements on the solids ("confirmed on
/// the exact solids").
enum class ExactBasis { kNone, kBound, kSolids };
const char* exact_basis_name(ExactBasis b);
ExactBasis exact_basis_from_name(const std::string& name);

struct ExactCheck {
  ExactVerdict verdict = ExactVerdict::kSkipped;
  ExactBasis basis = ExactBasis::kNone;
  std::optional<double> distance;  ///< between the solids (0: they meet), when measured
  /// The solids' overlap thickness (convex pairs: depth), certified [lower, upper].
  std::optional<std::array<double, 2>> depth_bounds;
  std::optional<double> volume;  ///< of the solids' common part, when the Boolean agreed
  double seconds = 0.0;          ///< spent on the solids
  std::string reason;            ///< why not decisive, or what was not trusted
};

/// "confirmed on the exact solids", "certified by the deflection bound", or a
/// sentence for an indecisive verdict: the words every writer uses.
std::string exact_sentence(const ExactCheck& e);

}  // namespace pd
