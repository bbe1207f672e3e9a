#pragma once
// One CLI subcommand: registers its options on construction, runs after a successful parse. Each
// command lives in its own command_*.cpp so commands grow without touching one another.
#include <CLI/CLI.hpp>
#include <memory>
#include <ostream>
#include <vector>

namespace collide::app {

struct CommandStreams {
  std::ostream& out;   // results
  std::ostream& err;   // notes, warnings, progress
  bool quiet = false;  // -q/--quiet: no progress or notes on err
};

class Command {
 public:
  virtual ~Command() = default;
  virtual CLI::App& cliApp() = 0;
  // Returns the exit code; throws core::Error subclasses for bad input or runtime failures.
  virtual int run(CommandStreams& streams) = 0;
};

// Every command, registered on `root` in the order `collide --help` lists them.
std::vector<std::unique_ptr<Command>> makeCommands(CLI::App& root);

std::unique_ptr<Command> makeRenderCommand(CLI::App& root);
std::unique_ptr<Command> makeStillCommand(CLI::App& root);
std::unique_ptr<Command> makeDataCommand(CLI::App& root);
std::unique_ptr<Command> makeLayoutCommand(CLI::App& root);
std::unique_ptr<Command> makeSolveCommand(CLI::App& root);
std::unique_ptr<Command> makePresetsCommand(CLI::App& root);
std::unique_ptr<Command> makeCheckCommand(CLI::App& root);
std::unique_ptr<Command> makeBatchCommand(CLI::App& root);
std::unique_ptr<Command> makeInfoCommand(CLI::App& root);
std::unique_ptr<Command> makeStrobeCommand(CLI::App& root);
std::unique_ptr<Command> makeChartCommand(CLI::App& root);
std::unique_ptr<Command> makeLessonCommand(CLI::App& root);
std::unique_ptr<Command> makeHelpManCommand(CLI::App& root);

}  // namespace collide::app
