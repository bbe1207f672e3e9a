#pragma once
// Private: how the program reaches the Cairo vector painter (vector_painter.hpp). Cairo brings
// pixman and, through Debian's build of it, libX11, libxcb and their kin: a dozen libraries that
// every process would load and search at start-up (each symbol the GL module's LLVM binds is
// looked up through them). So the painter lives in a module, collide-vector.so, opened the first
// time an SVG or PDF figure is made (vector_module_client.cpp), while its own tests link it
// directly (collide_render_vector). With COLLIDE_GL_MODULE=OFF the program links it too.
#include <string>

#include "frame/frame_model.hpp"
#include "render/vector/vector_painter.hpp"

namespace collide::render {

// The module's entry point, looked up by its C name: paintVectorFigure(frame, options) into
// `bytes`. options.font_path and options.text_fonts must be set (the caller resolves them: the
// module has its own copy of the process-wide font choice and of the active language). Errors
// travel as exceptions (the module and the program share libstdc++).
using PaintVectorFigureEntry = void (*)(const frame::FrameModel& frame,
                                        const VectorFigureOptions& options, std::string& bytes);
inline constexpr const char* kPaintVectorFigureSymbol = "collide_paint_vector_figure";

}  // namespace collide::render
