// collide info: version, GL backends compiled in, and the renderer each one reaches on this
// machine.
#include "app/command.hpp"
#include "app/version.hpp"
#include "render/backend.hpp"
#include "render/renderer.hpp"

namespace collide::app {
namespace {

class InfoCommand : public Command {
 public:
  explicit InfoCommand(CLI::App& root)
      : app_(*root.add_subcommand("info", "Show the version and the GL backends on this machine")) {
    app_.footer("Example:\n  collide info");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    streams.out << "collide " << kVersion << "\n";
    streams.out << "default backend: " << render::backendName(render::defaultBackend()) << "\n";
    for (render::Backend backend : render::compiledBackends()) {
      streams.out << "backend " << render::backendName(backend) << ": ";
      try {
        // A tiny renderer proves the context works end to end (FBO, shaders).
        render::Renderer renderer(backend, 16, 16);
        streams.out << renderer.glRendererName() << "\n";
      } catch (const render::RenderError& e) {
        streams.out << "unavailable (" << e.what() << ")\n";
      }
    }
    return 0;
  }

 private:
  CLI::App& app_;
};

}  // namespace

std::unique_ptr<Command> makeInfoCommand(CLI::App& root) {
  return std::make_unique<InfoCommand>(root);
}

}  // namespace collide::app
