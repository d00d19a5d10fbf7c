#include "results/exact_check.h"

#include <stdexcept>

namespace pd {

const char* exact_verdict_name(ExactVerdict v) {
  switch (v) {
    case ExactVerdict::kSkipped:
      return "skipped";
    case ExactVerdict::kInterference:
      return "interference";
    case ExactVerdict::kFalsePositive:
      return "false_positive";
    case ExactVerdict::kTouching:
      return "touching";
    case ExactVerdict::kSeparated:
      return "separated";
    case ExactVerdict::kInconsistent:
      return "inconsistent";
    case ExactVerdict::kFailed:
      return "failed";
    case ExactVerdict::kTimeout:
      return "timeout";
  }
  return "failed";
}

ExactVerdict exact_verdict_from_name(const std::string& name) {
  for (ExactVerdict v :
       {ExactVerdict::kSkipped, ExactVerdict::kInterference, ExactVerdict::kFalsePositive,
        ExactVerdict::kTouching, ExactVerdict::kSeparated, ExactVerdict::kInconsistent,
        ExactVerdict::kFailed, ExactVerdict::kTimeout})
    if (name == exact_verdict_name(v)) return v;
  throw std::invalid_argument("unknown exact verdict \"" + name + "\"");
}

const char* exact_basis_name(ExactBasis b) {
  switch (b) {
    case ExactBasis::kNone:
      return "none";
    case ExactBasis::kBound:
      return "deflection-bound";
    case ExactBasis::kSolids:
      return "exact-solids";
  }
  return "none";
}

ExactBasis exact_basis_from_name(const std::string& name) {
  for (ExactBasis b : {ExactBasis::kNone, ExactBasis::kBound, ExactBasis::kSolids})
    if (name == exact_basis_name(b)) return b;
  throw std::invalid_argument("unknown exact basis \"" + name + "\"");
}

std::string exact_sentence(const ExactCheck& e) {
  if (decisive(e.verdict))
    return e.basis == ExactBasis::kBound ? "certified by the deflection bound"
                                         : "confirmed on the exact solids";
  switch (e.verdict) {
    case ExactVerdict::kInconsistent:
      return "not confirmed: the exact solids disagree with the meshes (" + e.reason + ")";
    case ExactVerdict::kTimeout:
      return "not confirmed: the exact check ran out of time (" + e.reason + ")";
    case ExactVerdict::kFailed:
      return "not confirmed on the exact solids (" + e.reason + ")";
    default:
      return "not checked on the exact solids" + (e.reason.empty() ? "" : " (" + e.reason + ")");
  }
}

}  // namespace pd
