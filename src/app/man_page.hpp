#pragma once
// The collide(1) manual page, in roff, made from the same CLI11 definitions that print --help:
// every command, option, type, default and example comes from the command objects, so the page
// cannot drift from --help. The build runs `collide help-man` to write it.
#include <CLI/CLI.hpp>
#include <string>

namespace collide::app {

// The whole page for `root` (every visible command and subcommand), ready for man(1).
std::string manPage(const CLI::App& root);

// Escapes text for a roff text line: backslashes, hyphen-minus (so that options read and copy as
// ASCII '-') and control characters at the start of a line.
std::string roffEscape(const std::string& text);

}  // namespace collide::app
