// SPDX-License-Identifier: MIT
#include "app/cli_errors.hpp"

#include <cstdlib>

#include "core/typed_text.hpp"
#include "scene/suggest.hpp"

namespace collide::app {
namespace {

using Options = std::vector<const CLI::Option*>;

// The command the words were for: the deepest command the parser entered (root when none).
const CLI::App& commandOf(const CLI::App& root) {
  const CLI::App* at = &root;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  return *at;
}

// "collide data", "collide presets show".
std::string fullName(const CLI::App& command) {
  std::string name = command.get_name();
  for (const CLI::App* up = command.get_parent(); up != nullptr; up = up->get_parent()) {
    name = up->get_name() + " " + name;
  }
  return name;
}

std::string commandName(const CLI::App& command) {
  return "'" + fullName(command) + "'";
}

bool isHelp(const CLI::Option* option) {
  return option->check_name("--help");
}

// An option as --help names it: its long name, else its short one.
std::string shownName(const CLI::Option* option) {
  if (!option->get_lnames().empty()) return "--" + option->get_lnames().front();
  if (!option->get_snames().empty()) return "-" + option->get_snames().front();
  return option->get_name();
}

// The options --help lists (not the positional ones, nor --help itself, nor hidden ones).
Options typableOptions(const CLI::App& command) {
  return command.get_options([](const CLI::Option* option) {
    return !option->get_positional() && !isHelp(option) && !option->get_group().empty();
  });
}

// "-o/--output": every name of an option, as --help shows them.
std::string allNames(const CLI::Option* option) {
  std::string names;
  for (const std::string& name : option->get_snames()) names += (names.empty() ? "-" : "/-") + name;
  for (const std::string& name : option->get_lnames())
    names += (names.empty() ? "--" : "/--") + name;
  return names.empty() ? option->get_name() : names;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& word : words) out += (out.empty() ? "" : ", ") + word;
  return out;
}

// What a command takes, for "allowed: ...": its options, or its commands (the root).
std::string allowedOn(const CLI::App& command) {
  std::vector<std::string> names;
  if (command.get_parent() == nullptr) {
    for (const CLI::App* sub : command.get_subcommands([](const CLI::App*) { return true; })) {
      if (!sub->get_group().empty()) names.push_back(sub->get_name());
    }
    return "a command first: " + joined(names);
  }
  for (const CLI::Option* option : typableOptions(command)) names.push_back(shownName(option));
  for (const CLI::App* sub : command.get_subcommands([](const CLI::App*) { return true; })) {
    names.push_back(sub->get_name());
  }
  return joined(names) + " (see '" + fullName(command) + " --help')";
}

bool isNumber(const std::string& word) {
  char* end = nullptr;
  std::strtod(word.c_str(), &end);
  return !word.empty() && end != word.c_str() && *end == '\0';
}

bool looksLikeOption(const std::string& word) {
  return word.size() > 1 && word[0] == '-' && !isNumber(word);
}

// The word the user typed that the parser kept as `fragment`: itself, or the word of which the
// parser split it off ("-q=3" gives "-=3").
std::string typedWord(const std::string& fragment, const std::vector<std::string>& args) {
  for (const std::string& arg : args) {
    if (arg == fragment) return arg;
  }
  if (fragment.size() > 1 && fragment[0] == '-') {
    const std::string rest = fragment.substr(1);
    for (const std::string& arg : args) {
      if (arg.size() > rest.size() && arg[0] == '-' && arg.ends_with(rest)) return arg;
    }
  }
  return fragment;
}

// How the user wrote `option` ("-o" or "--output"), or how --help names it when not typed.
std::string typedName(const CLI::Option* option, const std::vector<std::string>& args) {
  for (const std::string& arg : args) {
    const std::string name = arg.substr(0, arg.find('='));
    if (looksLikeOption(name) && option->check_name(name)) return name;
  }
  return option->get_positional() ? option->get_name() : shownName(option);
}

int timesGiven(const CLI::Option* option, const std::vector<std::string>& args) {
  int times = 0;
  for (const std::string& arg : args) {
    const std::string name = arg.substr(0, arg.find('='));
    if (looksLikeOption(name) && option->check_name(name)) ++times;
  }
  return times;
}

// The other commands that take `name` ("render, still"), for a word given to the wrong one.
std::vector<std::string> commandsTaking(const CLI::App& root, const std::string& name) {
  std::vector<std::string> out;
  for (const CLI::App* sub : root.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_group().empty()) continue;
    if (sub->get_option_no_throw(name) != nullptr) out.push_back(sub->get_name());
  }
  return out;
}

std::string unknownOption(const CLI::App& root, const CLI::App& command, const std::string& typed) {
  const std::string name = typed.substr(0, typed.find('='));
  std::string message = "'" + core::echoTyped(name) + "': not an option of " + commandName(command);
  const std::vector<std::string> others = commandsTaking(root, name);
  if (!others.empty() && command.get_parent() != nullptr) {
    message += " (" + joined(others) + (others.size() == 1 ? " takes" : " take") + " it)";
  }
  std::vector<std::string> names;
  for (const CLI::Option* option : typableOptions(command)) names.push_back(shownName(option));
  return message + scene::didYouMean(name, names) + "; allowed: " + allowedOn(command);
}

// A word left over: an option this command does not have, or one argument too many.
std::string explainExtras(const CLI::App& root, const CLI::App& command,
                          const std::vector<std::string>& args) {
  std::vector<std::string> left = command.remaining(false);
  if (left.empty()) left = root.remaining(false);
  if (left.empty()) return commandName(command) + ": an argument it does not take";
  const std::string typed = typedWord(left.front(), args);
  if (looksLikeOption(typed)) {
    const CLI::Option* known = command.get_option_no_throw(typed.substr(0, typed.find('=')));
    if (known != nullptr && known->get_expected_max() == 0) {
      return "'" + core::echoTyped(typed) + "': " + typedName(known, args) +
             " takes no value; allowed: " + typedName(known, args) + " alone";
    }
    return unknownOption(root, command, typed);
  }
  const Options positionals =
      command.get_options([](const CLI::Option* option) { return option->get_positional(); });
  if (positionals.empty()) {
    return "'" + core::echoTyped(typed) + "': " + commandName(command) +
           " takes no arguments; allowed: " + allowedOn(command);
  }
  std::vector<std::string> given;
  for (const CLI::Option* option : positionals) {
    for (const std::string& value : option->results()) given.push_back(core::echoTyped(value));
  }
  return "'" + core::echoTyped(typed) + "': one argument more than " + commandName(command) +
         " takes (it has " + (given.empty() ? "none" : "'" + joined(given) + "'") +
         "); allowed: one " + positionals.front()->get_name() +
         ", then options: " + allowedOn(command);
}

// The option a parser message is about: "Could not convert: --dt = abc", "--csv: 1 required
// TEXT missing", "Expected exactly 1 arguments to --at, got 0", "The value x is not an allowed
// value for --y", "--output is required", "--a requires --b".
const CLI::Option* optionInMessage(const CLI::App& command, const std::string& message) {
  std::vector<std::string> candidates;
  const std::size_t convert = message.find("Could not convert: ");
  if (convert != std::string::npos) {
    const std::size_t from = convert + std::string("Could not convert: ").size();
    candidates.push_back(message.substr(from, message.find(" = ", from) - from));
  }
  if (const std::size_t to = message.find(" arguments to "); to != std::string::npos) {
    const std::size_t from = to + std::string(" arguments to ").size();
    candidates.push_back(message.substr(from, message.find(',', from) - from));
  }
  if (const std::size_t value_for = message.rfind(" value for "); value_for != std::string::npos) {
    candidates.push_back(message.substr(value_for + std::string(" value for ").size()));
  }
  candidates.push_back(message.substr(0, message.find(':')));
  candidates.push_back(message.substr(0, message.find(' ')));
  for (const std::string& name : candidates) {
    if (name.empty()) continue;
    if (const CLI::Option* option = command.get_option_no_throw(name)) return option;
  }
  return nullptr;
}

std::string allowedValues(const CLI::Option* option) {
  return option->get_description();
}

std::string explainMismatch(const CLI::Option* option, const std::vector<std::string>& args) {
  const std::string name = typedName(option, args);
  const int times = timesGiven(option, args);
  if (times > 1 && option->get_expected_max() <= 1) {
    return name + ": given " + std::to_string(times) + " times; allowed: once (" +
           allowedValues(option) + ")";
  }
  if (option->get_expected_max() == 0) {
    return name + ": takes no value; allowed: " + name + " alone";
  }
  return name + ": no value after it; allowed: " + allowedValues(option);
}

std::string kindOfValue(const CLI::Option* option) {
  const std::string type = option->get_type_name();
  if (type == "FLOAT") return "a number";
  if (type == "INT") return "a whole number";
  if (type == "UINT") return "a whole number, 0 or more";
  return "a value it takes";
}

std::string explainConversion(const CLI::Option* option, const std::vector<std::string>& args) {
  const std::string name = typedName(option, args);
  if (option->get_expected_max() == 0) {
    return name + ": takes no value; allowed: " + name + " alone";
  }
  const std::string value = option->results().empty() ? "" : option->results().back();
  return name + ": '" + core::echoTyped(value) + "' is not " + kindOfValue(option) +
         "; allowed: " + allowedValues(option);
}

std::string explainRequired(const CLI::App& root, const CLI::App& command,
                            const CLI::Option* option, const std::vector<std::string>& args) {
  if (option == nullptr) {  // no command
    if (!args.empty() && looksLikeOption(args.front())) {
      return unknownOption(root, root, args.front());
    }
    return "no command given; allowed: " + allowedOn(root);
  }
  const std::string name = allNames(option);
  return commandName(command) + ": " + name + " is missing; allowed: " + allowedValues(option);
}

// "--a requires --b", "--a excludes --b": both options named as typed.
std::string explainPair(const CLI::App& command, const std::string& message,
                        const std::string& joiner, const std::string& why,
                        const std::vector<std::string>& args) {
  const std::size_t at = message.find(joiner);
  const CLI::Option* first = command.get_option_no_throw(message.substr(0, at));
  const CLI::Option* second = at == std::string::npos
                                  ? nullptr
                                  : command.get_option_no_throw(message.substr(at + joiner.size()));
  if (first == nullptr || second == nullptr) return {};
  return typedName(first, args) + ": " + why + " " + typedName(second, args) + "; allowed: see '" +
         fullName(command) + " --help'";
}

}  // namespace

std::string explainParseError(const CLI::ParseError& error, const CLI::App& root,
                              const std::vector<std::string>& args) {
  const CLI::App& command = commandOf(root);
  const std::string message = error.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) {
    return explainExtras(root, command, args);
  }
  const CLI::Option* option = optionInMessage(command, message);
  if (dynamic_cast<const CLI::RequiredError*>(&error) != nullptr &&
      (option != nullptr || &command == &root)) {
    return explainRequired(root, command, option, args);
  }
  std::string pair;
  if (dynamic_cast<const CLI::RequiresError*>(&error) != nullptr) {
    pair = explainPair(command, message, " requires ", "needs", args);
  } else if (dynamic_cast<const CLI::ExcludesError*>(&error) != nullptr) {
    pair = explainPair(command, message, " excludes ", "cannot go with", args);
  }
  if (!pair.empty()) return pair;
  if (option != nullptr && dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
    return explainMismatch(option, args);
  }
  if (option != nullptr && dynamic_cast<const CLI::ConversionError*>(&error) != nullptr) {
    return explainConversion(option, args);
  }
  if (option != nullptr) {
    return typedName(option, args) + ": not a value it takes; allowed: " + allowedValues(option);
  }
  return commandName(command) + ": the command line cannot be read; allowed: " + allowedOn(command);
}

}  // namespace collide::app
