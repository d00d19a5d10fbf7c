// Finds the elements of one array in a JSON document without parsing them, so
// that a large scene's parts can be parsed on several threads.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pd {

/// Byte ranges in the text: the array value (brackets included) and each of
/// its elements (surrounding white space excluded).
struct ArraySpan {
  std::size_t begin = 0, end = 0;
  std::vector<std::pair<std::size_t, std::size_t>> elements;
};

/// The array stored under `key` in the top-level object of `text`. A structural
/// scan only (strings, escapes and bracket depth): it does not validate the
/// elements, whose own parse does. std::nullopt when the document is not an
/// object holding exactly one such key with an array value, a top-level key
/// has an escape, or its structure is broken; the caller then parses the whole
/// text, which reports the error.
std::optional<ArraySpan> top_level_array(std::string_view text, std::string_view key);

/// Like top_level_array, where `read` reads the array (ArraySpan::elements
/// stays empty): it is given the text from the array's '[' on and returns the
/// array's length in bytes, or 0 when it cannot read it (the result is then
/// std::nullopt). One pass over the array's bytes, not a scan for its end and
/// then a read.
std::optional<ArraySpan> read_top_level_array(
    std::string_view text, std::string_view key,
    const std::function<std::size_t(std::string_view)>& read);

}  // namespace pd
