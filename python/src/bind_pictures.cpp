// SPDX-License-Identifier: MIT
// Pictures and videos, drawn by the program's own pipelines (app/render_pipeline.hpp,
// app/picture_pipeline.hpp) into the file a path names, in any of the program's formats.
#include <pybind11/stl.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "app/output_options.hpp"
#include "app/picture_pipeline.hpp"
#include "app/render_pipeline.hpp"
#include "app/style_options.hpp"
#include "bindings.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"

namespace collide::python {
namespace {

// What every picture takes besides its scene and path.
struct Look {
  std::string lang;
  std::string theme, chart, panels;  // as --theme, --chart, --panels; empty: the scene's
  std::string size = "1280x720";     // as --size
};

Look lookFrom(const py::dict& options) {
  Look look;
  for (const auto& [key, value] : options) {
    if (value.is_none()) continue;
    const std::string name = key.cast<std::string>();
    if (name == "lang") look.lang = value.cast<std::string>();
    if (name == "theme") look.theme = value.cast<std::string>();
    if (name == "chart") look.chart = value.cast<std::string>();
    if (name == "panels") look.panels = value.cast<std::string>();
    if (name == "size") look.size = value.cast<std::string>();
  }
  return look;
}

// The scene in its picture's language (held by `hold`), with the look's style applied.
scene::SceneDesc pictureScene(const SceneRecipe& recipe, const Look& look,
                              std::unique_ptr<LanguageHold>& hold) {
  scene::SceneDesc loaded = loadForPicture(recipe, look.lang, hold);
  app::StyleOptions{look.theme, "", look.chart, look.panels}.applyTo(loaded);
  return loaded;
}

py::dict summaryOf(int images, const std::vector<std::string>& side_files,
                   const std::vector<std::string>& warnings) {
  py::dict summary;
  summary["images"] = images;
  summary["side_files"] = side_files;
  summary["warnings"] = warnings;
  return summary;
}

// A time in the scene, as `collide still --at` checks it.
void checkTime(double at_s, const std::string& typed, double duration_s) {
  if (std::isfinite(at_s) && at_s >= 0.0 && at_s <= duration_s) return;
  char allowed[80];
  std::snprintf(allowed, sizeof allowed, ": allowed: a time from 0 to %g s (the duration)",
                duration_s);
  throw core::InputError("at: " + core::echoTyped(typed) + allowed);
}

// A strobe rate, as `collide strobe --rate` checks it; `given` names it as given ("rate: 5000").
void checkRate(double rate_hz, const std::string& given, double duration_s) {
  if (std::isfinite(rate_hz) && rate_hz >= 0.1 && rate_hz <= 1000.0 &&
      rate_hz * duration_s <= 2000.0) {
    return;
  }
  char allowed[140];
  std::snprintf(allowed, sizeof allowed,
                ": allowed: 0.1 to 1000 images per second, at most 2000 images over the %g s "
                "scene",
                duration_s);
  throw core::InputError(given + allowed);
}

// `at` None: the middle of the scene, as the program's still.
py::dict still(const py::tuple& recipe_tuple, const std::string& path, std::optional<double> at_s,
               const std::string& at_typed, bool transparent, const py::dict& options) {
  const SceneRecipe recipe = recipeFrom(recipe_tuple);
  const Look look = lookFrom(options);
  app::RenderSummary summary;
  runReleased([&] {
    std::unique_ptr<LanguageHold> hold;
    app::StillRequest request{pictureScene(recipe, look, hold),
                              app::parseFrameSize(look.size),
                              0.0,
                              output::stillTarget(path),
                              {},
                              {},
                              {}};
    request.at_s = at_s.value_or(0.5 * request.scene.duration_s);
    if (at_s) checkTime(*at_s, at_typed, request.scene.duration_s);
    request.options.transparent = transparent;
    request.options.alt_text = false;  // the figure's own; the PNG's Description chunk has it
    summary = app::renderStill(request);
  });
  return summaryOf(summary.frames, summary.side_files, summary.warnings);
}

// `rate` None: the scene's view.strobe_rate, else chosen so that images do not overlap.
py::dict strobe(const py::tuple& recipe_tuple, const std::string& path,
                std::optional<double> rate_hz, const std::string& rate_typed,
                const py::dict& options) {
  const SceneRecipe recipe = recipeFrom(recipe_tuple);
  const Look look = lookFrom(options);
  app::PictureSummary summary;
  runReleased([&] {
    std::unique_ptr<LanguageHold> hold;
    const app::PictureRequest request{pictureScene(recipe, look, hold),
                                      app::parseFrameSize(look.size),
                                      output::stillTarget(path),
                                      std::nullopt,
                                      {}};
    double rate = request.scene.view.strobe_rate_hz;
    if (rate_hz) {
      checkRate(*rate_hz, "rate: " + core::echoTyped(rate_typed), request.scene.duration_s);
      rate = *rate_hz;
    } else if (rate != 0.0) {
      char given[60];
      std::snprintf(given, sizeof given, "view.strobe_rate: %g", rate);
      checkRate(rate, given, request.scene.duration_s);
    }
    summary = app::renderStrobe(request, rate);
  });
  py::dict result = summaryOf(summary.images, summary.side_files, summary.warnings);
  result["rate"] = summary.rate_hz;
  return result;
}

py::dict chart(const py::tuple& recipe_tuple, const std::string& path, const py::dict& options) {
  const SceneRecipe recipe = recipeFrom(recipe_tuple);
  const Look look = lookFrom(options);
  app::PictureSummary summary;
  runReleased([&] {
    std::unique_ptr<LanguageHold> hold;
    app::PictureRequest request{pictureScene(recipe, look, hold),
                                app::parseFrameSize(look.size),
                                output::stillTarget(path),
                                std::nullopt,
                                {}};
    // As `collide chart`: a scene with no chart of its own gets the energy chart.
    if (look.chart.empty() && !request.scene.view.chart) {
      request.scene.view.chart_quantity = "energy";
    }
    summary = app::renderChart(request);
  });
  return summaryOf(summary.images, summary.side_files, summary.warnings);
}

// MP4 (WebM, GIF, PNG frames by the path, as `collide render -o`), with WebVTT captions beside it
// when asked; `count` follows the frames drawn. Runs on the worker thread.
app::RenderSummary drawVideo(const SceneRecipe& recipe, const Look& look, const std::string& path,
                             int fps, bool captions, app::FrameCount& count) {
  app::checkFps(fps);
  std::unique_ptr<LanguageHold> hold;
  app::VideoRequest request{pictureScene(recipe, look, hold),
                            app::parseFrameSize(look.size),
                            fps,
                            output::videoTarget(path),
                            {}};
  const output::OutputKind kind = request.target.kind;
  if (kind == output::OutputKind::kGif && fps > app::kMaxGifFps) {
    throw core::InputError("fps: " + std::to_string(fps) + ": allowed for GIF: 1 to " +
                           std::to_string(app::kMaxGifFps) + " frames per second");
  }
  if (kind == output::OutputKind::kMp4 || kind == output::OutputKind::kWebm) {
    // H.264 and VP9 in 4:2:0 need even dimensions.
    request.size.width_px &= ~1;
    request.size.height_px &= ~1;
  }
  request.options.captions = captions;
  request.frame_count = &count;
  return app::renderVideo(request);
}

// The video; `progress`, if not None, is called as progress(frames_drawn, frames_total) while
// its frames are drawn (a notebook's progress bar).
py::dict video(const py::tuple& recipe_tuple, const std::string& path, int fps, bool captions,
               const py::dict& options, const py::object& progress) {
  const SceneRecipe recipe = recipeFrom(recipe_tuple);
  const Look look = lookFrom(options);
  app::RenderSummary summary;
  app::FrameCount count;
  const auto report = [&] {
    if (!progress.is_none() && count.total.load() > 0) {
      progress(count.drawn.load(), count.total.load());
    }
  };
  runReleased([&] { summary = drawVideo(recipe, look, path, fps, captions, count); }, report);
  py::dict result = summaryOf(summary.frames, summary.side_files, summary.warnings);
  result["size"] = py::make_tuple(summary.size.width_px, summary.size.height_px);
  return result;
}

}  // namespace

void bindPictures(py::module_& module) {
  module.def("still", &still, py::arg("recipe"), py::arg("path"), py::arg("at"),
             py::arg("at_typed"), py::arg("transparent"), py::arg("options"));
  module.def("strobe", &strobe, py::arg("recipe"), py::arg("path"), py::arg("rate"),
             py::arg("rate_typed"), py::arg("options"));
  module.def("chart", &chart, py::arg("recipe"), py::arg("path"), py::arg("options"));
  module.def("video", &video, py::arg("recipe"), py::arg("path"), py::arg("fps"),
             py::arg("captions"), py::arg("options"), py::arg("progress") = py::none());
}

}  // namespace collide::python
