// Usage errors as pdcheck says them: "pdcheck: error: …" like every other
// message, and for an option nobody knows, the nearest one it does know.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

/// The long option names of `app` and of its subcommands ("--tolerance", …).
std::vector<std::string> option_names(const CLI::App& app);

/// The known name nearest to `given` by edit distance, when it is near enough
/// to be a typo (at most a third of its length, and at most 3 edits); else "".
std::string nearest_option(const std::string& given, const std::vector<std::string>& known);

/// The message for a parse error: CLI11's text, and for arguments that were not
/// expected, "did you mean …?" for each that is near a known option.
std::string usage_message(const CLI::ParseError& e, const CLI::App& app);
