#include "report/fail_on.h"

namespace pd {

std::optional<FailOn> parse_fail_on(const std::string& name) {
  for (const auto& f : kFailOnNames)
    if (name == f.name) return f.value;
  return std::nullopt;
}

const char* fail_on_name(FailOn bar) {
  for (const auto& f : kFailOnNames)
    if (bar == f.value) return f.name;
  return "?";
}

bool is_finding(Status s) {
  return s == Status::kFalsePositive || s == Status::kInterference ||
         s == Status::kClearanceViolation;
}

bool reaches_bar(FailOn bar, Status s) {
  switch (bar) {
    case FailOn::kInterference:
      return s == Status::kInterference;
    case FailOn::kClearance:
    case FailOn::kNew:
      return s == Status::kInterference || s == Status::kClearanceViolation;
    case FailOn::kAny:
      return is_finding(s);
    case FailOn::kNone:
      return false;
  }
  return false;
}

FailOn default_fail_on(bool clearance_checked) {
  return clearance_checked ? FailOn::kClearance : FailOn::kInterference;
}

}  // namespace pd
