#include "results/pair_result.h"

#include <stdexcept>

#include "tolerances.h"

namespace pd {

const char* status_name(Status s) {
  switch (s) {
    case Status::kSeparated:
      return "separated";
    case Status::kFalsePositive:
      return "false_positive";
    case Status::kInterference:
      return "interference";
    case Status::kError:
      return "error";
    case Status::kClearanceViolation:
      return "clearance_violation";
    case Status::kUndecided:
      return "undecided";
  }
  return "error";
}

Status status_from_name(const std::string& name) {
  for (Status s : {Status::kSeparated, Status::kFalsePositive, Status::kInterference,
                   Status::kError, Status::kClearanceViolation, Status::kUndecided})
    if (name == status_name(s)) return s;
  throw std::invalid_argument("unknown status \"" + name + "\"");
}

Status classify(double depth, double tolerance, double pair_size) {
  if (depth <= tol::kTouch * pair_size) return Status::kSeparated;
  if (depth <= tolerance + tol::kClassifyBand * pair_size) return Status::kFalsePositive;
  return Status::kInterference;
}

}  // namespace pd
