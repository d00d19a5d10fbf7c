#include "usage_error.h"

#include <algorithm>
#include <sstream>

namespace {

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

void collect(const CLI::App& app, std::vector<std::string>& out) {
  for (const CLI::Option* o : app.get_options())
    for (const std::string& name : o->get_lnames()) out.push_back("--" + name);
  for (const CLI::App* sub : app.get_subcommands({})) collect(*sub, out);
}

}  // namespace

std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> out;
  collect(app, out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string nearest_option(const std::string& given, const std::vector<std::string>& known) {
  const std::string name = given.substr(0, given.find('='));  // --tolerence=0.1
  std::string best;
  size_t best_distance = std::min<size_t>(3, name.size() / 3) + 1;
  for (const std::string& k : known) {
    const size_t d = edit_distance(name, k);
    if (d < best_distance) best = k, best_distance = d;
  }
  return best;
}

std::string usage_message(const CLI::ParseError& e, const CLI::App& app) {
  std::string message = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e) == nullptr) return message;
  const std::vector<std::string> known = option_names(app);
  std::istringstream words(message.substr(message.find(':') + 1));
  std::string word;
  while (words >> word) {
    if (word.size() < 3 || word.compare(0, 2, "--") != 0) continue;
    const std::string near = nearest_option(word, known);
    if (!near.empty()) message += "; did you mean " + near + " (for " + word + ")?";
  }
  return message;
}
