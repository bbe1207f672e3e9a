#include "argv_entry.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "app/cli.hpp"
#include "core/typed_text.hpp"

namespace collide::fuzz {
namespace {

constexpr std::size_t kMaxArguments = 64;
// runCli cuts a message at 1000 characters of what it quotes; escaping a control character
// writes at most 4 ("\x01"); the prefix and the advice add a few dozen.
constexpr std::size_t kMaxMessageCharacters = 4 * 1000 + 3 + 100;

[[noreturn]] void finding(const std::string& what, const std::vector<std::string>& args) {
  std::string line = "collide";
  for (const std::string& arg : args) line += " '" + core::echoTyped(arg, 200) + "'";
  std::fprintf(stderr, "fuzz finding: %s\n  command line: %s\n", what.c_str(), line.c_str());
  std::abort();
}

}  // namespace

std::vector<std::string> argvFromBytes(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args;
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < kMaxArguments; ++i) {
    if (data[i] == '\0') {
      args.push_back(std::move(current));
      current.clear();
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  if (!current.empty() && args.size() < kMaxArguments) args.push_back(std::move(current));
  return args;
}

void fuzzCommandLine(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string> args = argvFromBytes(data, size);
  std::vector<const char*> argv = {"collide"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  argv.push_back(nullptr);
  std::ostringstream out, err;
  const int code = app::runCli(static_cast<int>(argv.size() - 1), argv.data(), out, err,
                               app::CliMode::kParseOnly);
  const std::string message = err.str();
  if (code == 0) {
    if (!message.empty()) finding("exit 0 with a message: " + core::echoTyped(message), args);
    return;
  }
  if (code != 2) finding("exit " + std::to_string(code) + " from parsing alone", args);
  if (!out.str().empty()) finding("exit 2 with output on stdout", args);
  if (message.rfind("collide: ", 0) != 0 || message.back() != '\n') {
    finding("not one 'collide: ...' line: " + core::echoTyped(message), args);
  }
  for (std::size_t i = 0; i + 1 < message.size(); ++i) {
    const auto c = static_cast<unsigned char>(message[i]);
    if (c < 0x20 || c == 0x7f) finding("a control character in: " + core::echoTyped(message), args);
  }
  if (core::utf8Length(message) > kMaxMessageCharacters) {
    finding("a message of " + std::to_string(core::utf8Length(message)) + " characters", args);
  }
}

}  // namespace collide::fuzz
