// Text from the input (part ids, paths) made safe for a log line.
#pragma once

#include <string>
#include <string_view>

namespace pd {

/// `text` with control characters escaped (\n, \r, \t, \e, \xNN; the C1
/// controls U+0080–U+009F as \u0080…): an id holding a newline or a terminal
/// escape sequence cannot start a forged log line or rewrite the terminal.
/// Everything else, UTF-8 included, is kept as it is.
std::string printable(std::string_view text);

}  // namespace pd
