// SVG and PDF figures painted by the module collide-vector.so, opened the first time one is made
// (see render/vector/vector_module.hpp): a PNG still, a video and `presets` never map Cairo.
#include <mutex>
#include <string>
#include <vector>

#include "core/module_loader.hpp"
#include "render/gl_context.hpp"
#include "render/text/script_fonts.hpp"
#include "render/text/text_metrics.hpp"
#include "render/vector/vector_module.hpp"

namespace collide::render {
namespace {

constexpr const char* kVectorModuleFile = "collide-vector.so";

std::mutex vector_module_mutex;
PaintVectorFigureEntry paint_entry =
    nullptr;  // guarded by vector_module_mutex; set once, never cleared

PaintVectorFigureEntry loadVectorModule() {
  std::vector<std::string> built_in;
#ifdef COLLIDE_VECTOR_MODULE_INSTALLED
  built_in.emplace_back(COLLIDE_VECTOR_MODULE_INSTALLED);
#endif
#ifdef COLLIDE_VECTOR_MODULE_BUILT
  built_in.emplace_back(COLLIDE_VECTOR_MODULE_BUILT);
#endif
  std::string error;
  void* entry =
      core::loadModuleSymbol(kVectorModuleFile, kPaintVectorFigureSymbol, built_in, error);
  if (entry == nullptr) throw RenderError("cannot write vector figures: " + error);
  return reinterpret_cast<PaintVectorFigureEntry>(entry);
}

}  // namespace

std::string paintVectorFigure(const frame::FrameModel& frame, const VectorFigureOptions& options) {
  PaintVectorFigureEntry entry = nullptr;
  {
    const std::lock_guard<std::mutex> lock(vector_module_mutex);
    if (paint_entry == nullptr) paint_entry = loadVectorModule();
    entry = paint_entry;
  }
  // The process-wide font choice (the CLI's --font) and the active language (--lang) live in the
  // program's copies of render and text.
  VectorFigureOptions resolved = options;
  if (resolved.font_path.empty()) resolved.font_path = defaultFontPath();
  if (resolved.text_fonts.files.empty()) resolved.text_fonts = textFontsFor(resolved.font_path);
  std::string bytes;
  entry(frame, resolved, bytes);
  return bytes;
}

}  // namespace collide::render
