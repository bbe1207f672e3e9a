// The entry point of collide-vector.so, the module that holds the Cairo vector painter and the
// libraries Cairo links (pixman, libX11 and libxcb through Debian's build): see
// render/vector/vector_module.hpp.
#include "render/vector/vector_module.hpp"

#include <type_traits>

extern "C" __attribute__((visibility("default"))) void collide_paint_vector_figure(
    const collide::frame::FrameModel& frame, const collide::render::VectorFigureOptions& options,
    std::string& bytes) {
  using namespace collide::render;
  static_assert(std::is_same_v<decltype(&collide_paint_vector_figure), PaintVectorFigureEntry>);
  bytes = paintVectorFigure(frame, options);
}
