#pragma once
// Private: turns a FrameModel into triangles in pixel coordinates, in drawing order.
#include <cstddef>

#include "render/frame_model.hpp"
#include "render/layout.hpp"
#include "render/mesh.hpp"

namespace collide::render {

// Speeds at or below this draw no arrow (m/s): a body at rest, up to solver round-off.
inline constexpr double kRestSpeed_mps = 1e-6;

struct FrameMeshRanges {
  std::size_t world_vertices = 0;  // track, bodies, arrows: drawn clipped to above the bar strip
  std::size_t total_vertices = 0;  // then the energy bar, unclipped
};

// Clears `mesh` and fills it with `frame` laid out by `layout`.
FrameMeshRanges buildFrameMesh(const FrameModel& frame, const FrameLayout& layout,
                               MeshBuilder& mesh);

}  // namespace collide::render
