// SPDX-License-Identifier: MIT
#pragma once
// The command-line parser's (CLI11's) errors in collide's words: one line that names what the
// user typed, what is wrong and what is allowed, never the parser's own phrasing ("The following
// arguments were not expected: de --lang"). The parser's message is read only for which option
// it is about; the rest comes from the command's own options and the words typed.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace collide::app {

// The message for `error`, thrown by root.parse() of `args` (argv without the program name).
std::string explainParseError(const CLI::ParseError& error, const CLI::App& root,
                              const std::vector<std::string>& args);

}  // namespace collide::app
