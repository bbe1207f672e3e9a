#pragma once
// Bodies that stuck together at e = 0 and move as one (a bullet embedded in its block, carts that
// coupled) are drawn and labelled as one body: the heaviest carries the one arrow and the labels
// ("m₁ + m₂ = 1.01 kg", "v₁′ = v₂′ = +1.98 m/s"); the others ride on it, drawn over it, a small
// one (the bullet) inside it. A stuck pair that spins (2D, partners moving differently) is left as
// it is: its bond and two arrows show the rotation.
#include <vector>

#include "frame/frame_model.hpp"

namespace collide::compose {

// `masses_kg` per body; `full_labels`: bodies carry mass and velocity labels (not crowded tags).
// Rewrites the bodies, labels and bonds of `panel`, whose bonds are those formed up to now.
void showMovingAsOne(frame::PanelModel& panel, const std::vector<double>& masses_kg,
                     bool full_labels);

}  // namespace collide::compose
