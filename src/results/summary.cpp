#include "results/summary.h"

namespace pd {

void Summary::add(Status s) {
  switch (s) {
    case Status::kSeparated:
      ++separated;
      break;
    case Status::kFalsePositive:
      ++false_positive;
      break;
    case Status::kInterference:
      ++interference;
      break;
    case Status::kError:
      ++error;
      break;
    case Status::kClearanceViolation:
      ++clearance_violation;
      break;
    case Status::kUndecided:
      ++undecided;
      break;
  }
}

}  // namespace pd
