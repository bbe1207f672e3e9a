#include "app/cli.hpp"

#include <ostream>

#include "app/command.hpp"
#include "app/version.hpp"
#include "core/error.hpp"
#include "output/video_sinks.hpp"

namespace collide::app {
int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App root{"collide: exact collision simulations rendered as teaching videos and stills",
                "collide"};
  root.set_version_flag("--version", std::string("collide ") + kVersion);
  root.require_subcommand(1);
  root.footer(
      "Examples:\n  collide render worked-example -o out/worked-example.mp4\n"
      "  collide still worked-example --at 2 -o still.png\n  collide presets");
  std::vector<std::unique_ptr<Command>> commands = makeCommands(root);

  // libx264 and libav print their settings and statistics otherwise; errors still show.
  output::setVideoLogLevel(output::CodecLogLevel::kErrors);
  try {
    root.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    out << (root.get_subcommands().empty() ? root.help() : root.get_subcommands().front()->help());
    return 0;
  } catch (const CLI::CallForVersion&) {
    out << "collide " << kVersion << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    err << "collide: " << e.what() << " (run 'collide --help')\n";
    return static_cast<int>(core::ExitCode::kBadInput);
  }

  CommandStreams streams{out, err};
  try {
    for (const std::unique_ptr<Command>& command : commands) {
      if (command->cliApp().parsed()) return command->run(streams);
    }
  } catch (const core::Error& e) {
    err << "collide: " << e.what() << "\n";
    return static_cast<int>(e.code());
  }
  return static_cast<int>(core::ExitCode::kBadInput);
}

}  // namespace collide::app
