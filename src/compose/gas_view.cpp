#include "compose/gas_view.hpp"

namespace collide::compose {

void drawAsGas(frame::PanelModel& panel) {
  panel.arrow_m_per_mps = 0.0;
  panel.scale_arrow_mps = 0.0;  // no arrows, no scale
  panel.scale_arrow_label.clear();
  panel.flashes.clear();
  for (frame::BodyModel& body : panel.bodies) {
    body.tag.clear();
    body.label.clear();
    body.velocity_label.clear();
  }
}

}  // namespace collide::compose
