#include "physics/event_hash.hpp"

#include <cstring>

namespace collide::physics {
namespace {

class Fnv1a {
 public:
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < size; ++k) hash_ = (hash_ ^ bytes[k]) * 0x100000001b3ull;
  }
  void add(double value) { add(&value, sizeof value); }
  void add(std::int64_t value) { add(&value, sizeof value); }
  void add(const core::Vec2& v) {
    add(v.x());
    add(v.y());
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace

std::uint64_t hashEventLog(const Timeline& timeline) {
  Fnv1a fnv;
  timeline.replayCollisions([&](const CollisionEvent& event) {
    fnv.add(event.index);
    fnv.add(event.time_s);
    fnv.add(std::int64_t{event.body_a});
    fnv.add(std::int64_t{event.body_b});
    fnv.add(event.restitution);
    fnv.add(event.normal);
    fnv.add(event.velocity_a_before_mps);
    fnv.add(event.velocity_a_after_mps);
    fnv.add(event.velocity_b_before_mps);
    fnv.add(event.velocity_b_after_mps);
    fnv.add(event.energy_lost_J);
    fnv.add(event.contact_duration_s);
  });
  fnv.add(timeline.collisionCount());
  fnv.add(timeline.totalEnergyLost());
  return fnv.value();
}

}  // namespace collide::physics
