// JSON text to a document, stricter than nlohmann::json::parse where the
// library is silent or vague: a key repeated in one object (the library keeps
// the last, other readers the first) and a number outside the double range
// (the library throws without a position) are errors naming the JSON path.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace pd {

/// Why a text is not a scene document. `byte` is where the parser stopped
/// (1-based, as nlohmann's parse_error::byte), 0 when unknown; `path` is the
/// JSON path of the offending element ("parts[2].id"), empty for the root.
class JsonTextError : public std::runtime_error {
 public:
  JsonTextError(const std::string& what, std::size_t byte, std::string path)
      : std::runtime_error(what), byte(byte), path(std::move(path)) {}
  std::size_t byte;
  std::string path;
};

/// Parses [begin, end) as one JSON document. Throws JsonTextError on a syntax
/// error, a duplicate key or a number literal beyond the double range.
nlohmann::json parse_json_strict(const char* begin, const char* end);

inline nlohmann::json parse_json_strict(const std::string& text) {
  return parse_json_strict(text.data(), text.data() + text.size());
}

}  // namespace pd
