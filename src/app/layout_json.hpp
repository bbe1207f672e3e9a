// SPDX-License-Identifier: MIT
#pragma once
// One item of `collide layout --json` (render/frame_layout.hpp's frame::DrawnItem) as the JSON
// object the command writes: its id, kind, text, box and what its kind adds.
#include "render/frame_layout.hpp"
#include "report/json_writer.hpp"

namespace collide::app {

// Pixels to the hundredth; "opacity" only for an item drawn at less than 1, to the thousandth.
void writeDrawnItem(report::JsonWriter& json, const frame::DrawnItem& item);

}  // namespace collide::app
