#pragma once
// Internal: the event-driven engine of 2D worlds in which bodies hang on strings (a Newton's
// cradle, a ballistic pendulum). Between events a unit on a taut string follows the exact
// pendulum solution, any other unit its parabola. Events: impacts of bodies with bodies and
// walls (times from bracketed_contact.hpp, impulses from string_impact.hpp), a string going
// slack where its tension reaches zero, and a slack string snapping taut (a jerk along the
// string whose energy is booked as lost). After every event all predictions are made afresh from
// the present states and time, so a replay from a checkpoint repeats the run bit for bit.
//
// Perfectly inelastic impacts (e = 0) join the partners into one unit, one pendulum with the
// combined mass hanging at the combined centre of mass, where that is a pendulum: a free body
// into a hanging one (the bullet stops inside the block: it is moved, with the potential energy
// of that step booked, to just inside the face it hit), or two hanging bodies on strings of
// equal length at equal angles (their parallel strings carry them as one). Units translate; they
// never turn (a block on two parallel strings).
//
// Contacts that persist (string_groups.cpp): bodies on strings of one length that swing in step
// touching, their relative motion below what the books resolve, go on as one group that parts
// again when struck (a merge that is no bond).
#include <cstdint>
#include <optional>
#include <vector>

#include "physics/engine.hpp"
#include "physics/pendulum_motion.hpp"
#include "physics/string_impact.hpp"
#include "physics/swing_pair_bound.hpp"

namespace collide::physics::detail {

class StringEngine final : public Engine {
 public:
  StringEngine(const Model& model, EngineState start, const Recorder& out);
  RunStop run(double t_end_s, std::int64_t count_limit) override;
  const EngineState& state() const override { return state_; }

 private:
  enum class Kind { kPair, kWall, kSlack, kTaut };
  struct Event {
    double time_s = 0.0;
    Kind kind = Kind::kPair;
    int a = 0, b = 0;  // bodies (a < b); body and wall; unit and 0
    // Impacts due at once (a row of touching balls): the hardest first, so that the order
    // follows the motion, not the numbering.
    double closing_mps = 0.0;
  };
  struct Kin {
    core::Vec2 x, v;
  };

  Kin unitAt(int unit, double t) const;
  Kin bodyAt(int body, double t) const;
  bool taut(int unit) const { return state_.swings[unit].taut; }
  void refreshArc(int unit);
  // Bounds over [t0, t1] on a unit's speed and acceleration.
  double speedBound(int unit, double t0, double t1) const;
  double accelBound(int unit, double speed_bound) const;

  // Two units on taut strings of one length at t, for swingPairCurvature_mps2.
  SwingPair swingPair(int ua, int ub, double t, double reach_m) const;
  // Predictions (string_predict.cpp): absolute times, infinite for none before t_end.
  double predictPair(int a, int b, double t_end) const;
  double predictWall(int body, int wall, double t_end) const;
  std::optional<Event> predictString(int unit) const;
  std::optional<Event> nextEvent(double t_end) const;

  // Responses (string_respond.cpp).
  void pairImpact(int a, int b, double t);
  void wallImpact(int body, int wall, double t);
  void goSlack(int unit, double t);
  void snapTaut(int unit, double t);
  bool tryMerge(int a, int b, double t, double closing, const core::Vec2& n);
  // The steps of tryMerge: which unit keeps its string (`host`) and which joins it (`guest`), and
  // for a free body into a hanging one the body hit and the body hitting it (else -1); none where
  // the two cannot merge.
  struct MergeRoles {
    int host = -1, guest = -1, hit = -1, hitter = -1;
  };
  std::optional<MergeRoles> mergeRoles(int a, int b, double t) const;
  // Joins the guest into the host (momentum kept but what the host's string takes); the record.
  CollisionEvent merge(const MergeRoles& roles, int a, int b, double t, double closing,
                       const core::Vec2& n);
  // Where the guest moves as it joins (a smaller body ends inside the one it hit).
  core::Vec2 guestShift(const MergeRoles& roles, double t) const;
  // The guest's bodies join the host unit, now of `mass` with its centre of mass at `centre`.
  void joinGuest(const MergeRoles& roles, const core::Vec2& host_x, const core::Vec2& guest_x,
                 const core::Vec2& shift, const core::Vec2& centre, double mass);
  // Sets a unit moving from x, v at t: on its string when `on_string` and the string can pull,
  // otherwise on its parabola.
  // Contacts that persist (string_groups.cpp): two bodies swinging in step, touching, whose
  // relative motion is below what the books resolve, go on as one group; a group struck parts.
  bool joinable(int unit) const;
  bool joinsInStep(int a, int b, double t) const;
  // Taut, or slack for a moment: on its circle, moving along the string with less than floor_J.
  bool onCircleGently(int unit, double t, double floor_J) const;
  void joinInStep(int a, int b, double t, double closing, const core::Vec2& n, double e);
  void splitGroup(int unit, double t);
  void restart(int unit, double t, const core::Vec2& x, const core::Vec2& v, bool on_string);
  ImpactPartner partner(int unit, double t) const;
  void record(CollisionEvent event);

  const Model& model_;
  EngineState state_;
  Recorder out_;
  double gravity_m_s2_ = 0.0;
  std::vector<std::optional<PendulumArc>> arcs_;  // per unit, while taut
  std::int64_t same_time_events_ = 0;
};

}  // namespace collide::physics::detail
