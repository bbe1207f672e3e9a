// SPDX-License-Identifier: MIT
// The extension module collide._collide: the engine's scenes, simulations and pictures for the
// Python package (python/collide), which gives them their Python shape.
#include <pybind11/pybind11.h>

#include <filesystem>

#include "bindings.hpp"
#include "core/error.hpp"
#include "core/stop_request.hpp"
#include "core/typed_text.hpp"
#include "output/stop_signals.hpp"
#include "output/video_sinks.hpp"

namespace collide::python {
namespace {

// One line whatever the message holds, as the program prints it after "collide: ".
std::string oneLine(const std::string& message) {
  return core::echoTyped(message, 1000);
}

}  // namespace

void bindErrors(py::module_& module) {
  // Bad input (exit 2 in the program) is a ValueError; a failure at run time (exit 1) a
  // RuntimeError; a stop request the KeyboardInterrupt that asked for it.
  static py::exception<core::InputError> scene_error(module, "SceneError", PyExc_ValueError);
  static py::exception<core::RuntimeError> run_error(module, "CollideError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const core::StopRequested&) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const core::InputError& e) {
      scene_error(oneLine(e.what()).c_str());
    } catch (const core::Error& e) {
      run_error(oneLine(e.what()).c_str());
    } catch (const std::filesystem::filesystem_error& e) {
      const std::string message =
          "'" + oneLine(e.path1().string()) + "': " + oneLine(e.code().message());
      run_error(message.c_str());
    }
  });
}

SceneRecipe recipeFrom(const py::tuple& recipe) {
  SceneRecipe result;
  result.source = recipe[0].cast<std::string>();
  result.is_text = recipe[1].cast<bool>();
  result.text_name = recipe[2].cast<std::string>();
  for (const py::handle item : recipe[3].cast<py::list>()) {
    const py::tuple change = item.cast<py::tuple>();
    scene::Override override{change[0].cast<std::string>(), change[1].cast<std::string>(),
                             change[2].cast<std::string>(),
                             static_cast<scene::Override::Kind>(change[3].cast<int>())};
    result.overrides.push_back(override);
  }
  if (!recipe[4].is_none()) {
    result.duration_s = recipe[4].cast<double>();
    result.duration_typed = recipe[5].cast<std::string>();
  }
  return result;
}

}  // namespace collide::python

PYBIND11_MODULE(_collide, module) {
  using namespace collide;
  module.doc() = "collide's engine: scenes, exact simulations, pictures and videos";
  // The interpreter owns SIGINT; runReleased passes a KeyboardInterrupt on as a stop request.
  output::StopSignals::leaveToHost();
  // libx264 and libav print their settings and statistics otherwise; errors still show.
  output::setVideoLogLevel(output::CodecLogLevel::kErrors);
  python::bindErrors(module);
  python::bindScene(module);
  python::bindRun(module);
  python::bindPictures(module);
  python::bindSolve(module);
}
