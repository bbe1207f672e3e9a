#include "app/backend_option.hpp"

#include "core/error.hpp"
#include "render/backend.hpp"

namespace collide::app {

void BackendOption::addTo(CLI::App& command) {
  command.add_option("--backend", name,
                     "GL backend: osmesa (default), egl (surfaceless, same pixels), gpu (EGL "
                     "device), auto (gpu, then egl, then osmesa)");
}

void BackendOption::apply() const {
  if (name.empty()) return;
  const std::optional<render::Backend> backend = render::parseBackend(name);
  if (!backend) {
    throw core::InputError("--backend: '" + name + "': allowed: osmesa, egl, gpu, auto");
  }
  render::setDefaultBackend(*backend);
}

}  // namespace collide::app
