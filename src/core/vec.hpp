#pragma once
// Vector aliases used across modules. Positions in metres, velocities in m/s unless a name says
// otherwise.
#include <Eigen/Core>

namespace collide::core {

using Vec2 = Eigen::Vector2d;

}  // namespace collide::core
