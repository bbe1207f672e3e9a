#pragma once
// The physics symbols and punctuation that pictures, captions and alt text share, in the active
// language: the symbols as that language's physics textbooks write them (German school books write
// E_kin where English ones write KE), and the separators between clauses and list items (Arabic
// writes "؛" and "،", Chinese "；" and "，"). SI unit symbols are never translated.
#include <string>
#include <string_view>
#include <vector>

namespace collide::text {

enum class Symbol {
  kTime,             // t
  kMass,             // m
  kVelocity,         // v
  kMomentum,         // p
  kRestitution,      // e, the coefficient of restitution
  kKineticEnergy,    // KE
  kPotentialEnergy,  // PE
  kPosition,         // x
  kForce,            // F
  kAngularVelocity,  // ω
};

std::string symbol(Symbol which);

// "; " between the clauses of a caption or info line, ", " between the items of a list.
std::string clauseSeparator();
std::string listSeparator();

// Between two sentences: a space, or nothing in Chinese and Japanese (their full stop "。" is
// the gap).
std::string sentenceGap();

// "a, b and c": items joined by the list separator, the last two by the language's "and".
std::string listWithAnd(const std::vector<std::string>& items);

// The sentence with its first letter in upper case as the active language writes it (Turkish "i"
// becomes "İ"): alt text and narration start sentences with a body's name, and preset names are
// lower case ("cart 1 (1 kg) is at ..."). Anything else at the start (a digit, a symbol, a script
// without case) comes back unchanged.
std::string sentenceStart(std::string_view sentence);

// "name = value", the way every readout and label is written.
std::string equation(const std::string& name, const std::string& value);

}  // namespace collide::text
