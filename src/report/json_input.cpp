#include "report/json_input.h"

#include <fstream>
#include <sstream>

namespace pd {

nlohmann::json parse_json_input(const std::string& text, const std::string& path) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // The byte offset as a line and column a person can find.
    const size_t at = std::min<size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    size_t line = 1, col = 1;
    for (size_t k = 0; k < at; ++k) {
      if (text[k] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    throw ReportInputError(path + ":" + std::to_string(line) + ":" + std::to_string(col) +
                           ": invalid JSON");
  }
}

std::string read_input_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ReportInputError(path + ": cannot read the file");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void JsonAt::fail(const std::string& what) const {
  throw ReportInputError(file + ": " + where + ": " + what);
}

JsonAt JsonAt::operator[](const char* key) const {
  object();
  if (!value.contains(key)) fail(std::string("missing required key \"") + key + "\"");
  return {value.at(key), file, where + "." + key};
}

JsonAt JsonAt::operator[](size_t k) const {
  return {array().at(k), file, where + "[" + std::to_string(k) + "]"};
}

const nlohmann::json& JsonAt::object() const {
  if (!value.is_object()) fail("must be an object");
  return value;
}

const nlohmann::json& JsonAt::array() const {
  if (!value.is_array()) fail("must be an array");
  return value;
}

std::string JsonAt::string() const {
  if (!value.is_string()) fail("must be a string");
  return value.get<std::string>();
}

double JsonAt::number() const {
  if (!value.is_number()) fail("must be a number");
  return value.get<double>();
}

void JsonAt::only_keys(std::initializer_list<const char*> known) const {
  for (const auto& item : object().items()) {
    bool ok = false;
    for (const char* k : known) ok |= item.key() == k;
    if (!ok) JsonAt{item.value(), file, where + "." + item.key()}.fail("unknown key");
  }
}

}  // namespace pd
