// Text escaped for XML 1.0 and HTML (JUnit, the HTML report): one rule for both.
#pragma once

#include <string>

namespace pd {

/// & < > " ' become entities; control characters XML cannot carry become '?'.
/// Safe in element text and in quoted attributes of both languages.
std::string markup_escape(const std::string& s);

}  // namespace pd
