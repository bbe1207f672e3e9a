// collide help-man: prints the collide(1) manual page in roff. Hidden from --help (the build runs
// it to write the page); the page is made from the same command definitions as --help.
#include "app/command.hpp"
#include "app/man_page.hpp"

namespace collide::app {
namespace {

class HelpManCommand : public Command {
 public:
  explicit HelpManCommand(CLI::App& root)
      : root_(root),
        app_(*root.add_subcommand("help-man", "Print the collide(1) manual page (roff)")) {
    app_.group("");  // hidden: not a command a teacher needs to see in --help
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    streams.out << manPage(root_);
    return 0;
  }

 private:
  const CLI::App& root_;
  CLI::App& app_;
};

}  // namespace

std::unique_ptr<Command> makeHelpManCommand(CLI::App& root) {
  return std::make_unique<HelpManCommand>(root);
}

}  // namespace collide::app
