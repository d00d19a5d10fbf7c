#include "report/prior_settings.h"

#include "report/finding_text.h"

namespace pd {

std::vector<std::string> check_prior_settings(const std::string& option, const std::string& path,
                                              const PriorSettings& prior,
                                              const ReportContext& run) {
  const std::string who = option + " " + path;
  if (prior.units && *prior.units != run.units)
    throw ReportInputError(who + ": the report is in " + *prior.units + ", this run in " +
                           run.units + ": its depths cannot be compared with this run's (run in " +
                           *prior.units + ", or write a new report in " + run.units + ")");
  std::vector<std::string> warnings;
  const bool other_tolerance =
      prior.auto_tolerance
          ? !run.auto_tolerance
          : prior.tolerance && (run.auto_tolerance || *prior.tolerance != run.tolerance);
  if (other_tolerance)
    warnings.push_back(who + ": written with tolerance " +
                       (prior.auto_tolerance ? std::string("auto")
                                             : short_number(*prior.tolerance) + " " + run.units) +
                       ", this run's is " + tolerance_words(run) +
                       ": a status may differ by the tolerance alone");
  if (prior.method) {
    // Both sides through the same JSON type, so that key order does not count.
    const nlohmann::json now = nlohmann::json::parse(method_json(run.solver).dump());
    if (*prior.method != now)
      warnings.push_back(who + ": written with method " + prior.method->dump() +
                         ", this run uses " + now.dump() +
                         ": a depth may differ by the method alone");
  }
  if (prior.rules_hash && *prior.rules_hash != run.rules_hash)
    warnings.push_back(
        who + ": written " +
        (prior.rules_hash->empty() ? std::string("without rules")
                                   : "under other rules (hashes.rules " + *prior.rules_hash + ")") +
        ", this run " +
        (run.rules_hash.empty() ? std::string("has none") : "has hashes.rules " + run.rules_hash) +
        ": which pairs are checked, their tolerances and expected contacts may differ by the "
        "rules alone (a pair decided against another tolerance is solved again)");
  return warnings;
}

}  // namespace pd
