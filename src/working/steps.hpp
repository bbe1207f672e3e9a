// SPDX-License-Identifier: MIT
#pragma once
// The parts every working is made of: the impact it is about, the words of its steps, and the
// arithmetic written as math (products, sums, differences).
#include <string>
#include <vector>

#include "physics/timeline.hpp"
#include "text/math.hpp"
#include "working/notation.hpp"
#include "working/working.hpp"

namespace collide::working {

struct Impact {
  const physics::Timeline& timeline;
  const physics::CollisionEvent& event;
  Formats formats;
  int dimensions = 1;
};

// A step with its heading in the active language.
Step step(StepKind kind);
// The step of that kind in `working`, added at the end when there is none yet.
Step& stepOf(Working& working, StepKind kind);

// "a · b · c", each factor bracketed where it needs it ("a × b × c" where the digits' zero is a
// dot, as in Arabic: text::multiplicationSign).
text::Math product(std::vector<text::Math> factors);
// "a b", juxtaposed symbols (m₁v₁).
text::Math juxtaposed(std::vector<text::Math> factors);
text::Math sum(text::Math left, text::Math right);
text::Math difference(text::Math left, text::Math right);

// The kinds of impact, each adding its steps to `working`.
void addTwoBodies(const Impact& impact, Working& working);
void addWall(const Impact& impact, Working& working);
void addBouncingBall(const Impact& impact, Working& working);
void addBallisticPendulum(const Impact& impact, Working& working);
void addCradle(const Impact& impact, Working& working);
void addPiBlocks(const Impact& impact, Working& working);
void addSoftContact(const Impact& impact, Working& working);
void addStuckCluster(const Impact& impact, Working& working);
void addRestitutionLaw(const Impact& impact, Working& working);
// An accident reconstruction (skid.cpp): a body skids into one at rest, they lock and skid to
// rest; the speeds read back from the skids. False, adding nothing, where the impact is not one.
bool addSkid(const Impact& impact, Working& working);
// A release: stored energy pushing two touching bodies apart (release.cpp).
void addRelease(const Impact& impact, Working& working);

// The energy an impact turns over (release.cpp): lost, ΔKE = ½m(1 − e²)u², where e <= 1;
// released, Q = ½m(e² − 1)u², where e > 1 (super-elastic).
text::Math releasedSymbol();  // Q
bool gainsEnergy(double e);
text::Math energyChangeSymbol(double e);  // ΔKE or Q
// (1 − e²), or (e² − 1) where e > 1, with `e_shown` for e (its symbol or its value).
text::Math restitutionFactor(text::Math e_shown, double e);
std::string energyChangeNote(double e);
double energyChange_J(double m_kg, double u_mps, double e);  // ½m|1 − e²|u²
// The result's line: the energy the simulation booked as lost, or as released where e > 1.
Equation energyChangeResult(const Impact& impact);

}  // namespace collide::working
