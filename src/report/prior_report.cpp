#include "report/prior_report.h"

#include <nlohmann/json.hpp>

#include "report/json_input.h"
#include "results/codec.h"
#include "results/fingerprint.h"

namespace pd {

PriorResults load_prior_report(const std::string& path, PriorSettings* settings) {
  const std::string text = read_input_file(path);
  nlohmann::ordered_json doc;
  try {
    doc = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw ReportInputError(path + ": not a JSON report (" + e.what() + ")");
  }
  PriorResults prior;
  prior.path = path;
  if (settings) *settings = prior_settings_of(doc);
  try {
    if (!doc.contains("hashes") || !doc["hashes"].contains("settings"))
      throw ReportInputError(path +
                             ": $.hashes: missing; --reuse needs a report written with content "
                             "hashes (this version of pdcheck writes them)");
    prior.settings_hash = doc["hashes"]["settings"].get<std::string>();
    std::map<std::string, int> index;
    const auto& parts = doc.at("parts");
    for (size_t k = 0; k < parts.size(); ++k) {
      const std::string id = parts[k].at("id").get<std::string>();
      index[id] = static_cast<int>(k);
      if (parts[k].contains("content_hash") && !parts[k].contains("error"))
        prior.part_hash[id] = parts[k]["content_hash"].get<std::string>();
    }
    const auto& pairs = doc.at("pairs");
    for (size_t k = 0; k < pairs.size(); ++k) {
      const auto& p = pairs[k];
      const std::string a = p.at("a").get<std::string>(), b = p.at("b").get<std::string>();
      try {
        prior.pairs[pair_fingerprint(a, b)] = pair_from_report(p, -1, -1);
      } catch (const std::exception& e) {
        throw ReportInputError(path + ": $.pairs[" + std::to_string(k) + "]: " + e.what());
      }
    }
  } catch (const nlohmann::json::exception& e) {
    throw ReportInputError(path + ": not a pdcheck report: " + e.what());
  }
  return prior;
}

}  // namespace pd
