// pdcheck's exit codes (README, docs/ci.md) and the one rule that orders them:
// below every layer, as every layer's user errors carry one (user_error.h).
#pragma once

namespace pd {

/// The process's exit status. Unscoped on purpose: it leaves the program as an int.
enum ExitCode : int {
  kExitClean = 0,       ///< everything checked, nothing fails the run
  kExitFinding = 1,     ///< a finding fails the run (or a stale suppression)
  kExitBadInput = 2,    ///< bad input or usage, or the report could not be delivered
  kExitIncomplete = 3,  ///< something was not checked or not decided: wins over 1
};

/// A run's exit code: incomplete wins, then failing, else clean.
constexpr ExitCode run_exit_code(bool incomplete, bool failing) {
  return incomplete ? kExitIncomplete : failing ? kExitFinding : kExitClean;
}

}  // namespace pd
