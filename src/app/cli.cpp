#include "app/cli.hpp"

#include <filesystem>
#include <ostream>

#include "app/cli_errors.hpp"
#include "app/command.hpp"
#include "app/simulation_progress.hpp"
#include "app/version.hpp"
#include "core/bounded_read.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "output/video_sinks.hpp"
#include "render/text/text_metrics.hpp"
#include "scene/suggest.hpp"
#include "text/language.hpp"

namespace collide::app {
namespace {

// The longest message printed: a value typed a megabyte long is cut (core::echoTyped cuts each
// echoed value at 80 characters; this catches any echo that slipped past).
constexpr std::size_t kMaxMessageCharacters = 1000;

// One line whatever the message holds: control characters escaped, the length bounded.
std::string oneLine(const std::string& message) {
  return core::echoTyped(message, kMaxMessageCharacters);
}

// "collide rendr" names no command: say which is closest and list them all, instead of CLI11's
// "A subcommand is required".
void refuseUnknownCommand(const CLI::App& root, int argc, const char* const* argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  const std::string typed = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* command : root.get_subcommands([](const CLI::App*) { return true; })) {
    if (command->get_name() == typed) return;
    // Hidden commands (an empty group, e.g. help-man for the build) are not offered.
    if (!command->get_group().empty()) names.push_back(command->get_name());
  }
  std::string allowed;
  for (const std::string& name : names) allowed += (allowed.empty() ? "" : ", ") + name;
  const std::vector<std::string> near = scene::nearMatches(typed, names);
  throw core::InputError("'" + core::echoTyped(typed) + "': unknown command" +
                         (near.empty() ? "" : "; did you mean '" + near.front() + "'?") +
                         "; allowed: " + allowed);
}

// -q/--quiet on every command (render registers its own with its output options).
void addQuietFlags(CLI::App& root, bool& quiet) {
  for (CLI::App* command : root.get_subcommands([](CLI::App*) { return true; })) {
    if (command->get_option_no_throw("--quiet") != nullptr) continue;
    command->add_flag("-q,--quiet", quiet, "No progress or notes on stderr (errors still show)");
  }
}

bool quietAsked(const CLI::App& root) {
  for (const CLI::App* command : root.get_subcommands([](const CLI::App*) { return true; })) {
    const CLI::Option* option = command->get_option_no_throw("--quiet");
    if (command->parsed() && option != nullptr && option->count() > 0) return true;
  }
  return false;
}

}  // namespace

int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err, CliMode mode) {
  CLI::App root{"collide: exact collision simulations rendered as teaching videos and stills",
                "collide"};
  root.set_version_flag("--version", std::string("collide ") + kVersion);
  root.require_subcommand(1);
  root.footer(
      "Examples:\n  collide render worked-example -o out/worked-example.mp4\n"
      "  collide still worked-example --at 2 -o still.png\n  collide presets");
  std::vector<std::unique_ptr<Command>> commands = makeCommands(root);
  bool quiet = false;
  addQuietFlags(root, quiet);

  // libx264 and libav print their settings and statistics otherwise; errors still show.
  output::setVideoLogLevel(output::CodecLogLevel::kErrors);
  try {
    refuseUnknownCommand(root, argc, argv);
    root.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    out << (root.get_subcommands().empty() ? root.help() : root.get_subcommands().front()->help());
    return 0;
  } catch (const CLI::CallForVersion&) {
    out << "collide " << kVersion << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    const std::vector<std::string> args(argv + std::min(argc, 1), argv + argc);
    err << "collide: " << oneLine(explainParseError(e, root, args)) << "\n";
    return static_cast<int>(core::ExitCode::kBadInput);
  } catch (const core::InputError& e) {
    err << "collide: " << oneLine(e.what()) << "\n";
    return static_cast<int>(e.code());
  }

  if (mode == CliMode::kParseOnly) return 0;
  core::forgetInputFiles();  // what an earlier run in this process read is not this one's input

  CommandStreams streams{out, err, quietAsked(root)};
  // -q: nothing but errors, the libraries' notes included (Mesa's are kept away by the renderer).
  render::showFontconfigMessages(!streams.quiet);
  // A simulation that runs over 2 s says how far it has got (see simulation_progress.hpp).
  const SimulationReportScope simulation_report(err, core::chooseProgressStyle(err, streams.quiet));
  // The language a command chooses (--lang, a scene's lang) is that run's: a process that runs
  // more than one (the Python package, a test binary) finds the language as it was before.
  const text::ScopedLanguage language_of_this_run(text::activeLanguage().tag);
  try {
    for (const std::unique_ptr<Command>& command : commands) {
      if (command->cliApp().parsed()) return command->run(streams);
    }
  } catch (const core::Error& e) {
    err << "collide: " << oneLine(e.what()) << "\n";
    return static_cast<int>(e.code());
  } catch (const std::filesystem::filesystem_error& e) {
    // Every file system call on a path a user gives says what went wrong itself; one that did
    // not still names the path and the reason, as a runtime failure, never an internal error.
    err << "collide: '" << oneLine(e.path1().string()) << "': " << oneLine(e.code().message())
        << "\n";
    return static_cast<int>(core::ExitCode::kRuntimeFailure);
  }
  return static_cast<int>(core::ExitCode::kBadInput);
}

}  // namespace collide::app
