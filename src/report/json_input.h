// Reading a small JSON input file (baseline, suppressions) with messages that
// name the file and the JSON path of the offending value.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "report/input_error.h"

namespace pd {

/// Parses `text` (named `path` in messages); invalid JSON throws
/// ReportInputError with the line and column.
nlohmann::json parse_json_input(const std::string& text, const std::string& path);

/// Reads a whole file (throws ReportInputError naming it when unreadable).
std::string read_input_file(const std::string& path);

/// A value at a JSON path ("$.pairs[3]") of a file, for typed access with
/// errors that say where.
struct JsonAt {
  const nlohmann::json& value;
  std::string file, where;

  [[noreturn]] void fail(const std::string& what) const;
  bool has(const char* key) const { return value.is_object() && value.contains(key); }
  JsonAt operator[](const char* key) const;
  JsonAt operator[](size_t k) const;
  const nlohmann::json& object() const;  ///< throws unless an object
  const nlohmann::json& array() const;   ///< throws unless an array
  std::string string() const;
  double number() const;
  /// Throws on a key outside `known` (a typo never passes silently).
  void only_keys(std::initializer_list<const char*> known) const;
};

}  // namespace pd
