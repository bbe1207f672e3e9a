#pragma once
// The placeholder check of a compiled catalogue: every translation names the same placeholders
// as its original ("{mass} at {speed}"), so no value is lost or left as "{name}" on a picture. A
// plural form may leave out only {count} (Arabic's forms for one and two say the number in the
// word).
#include <string>
#include <vector>

#include "text/catalog.hpp"

namespace collide::text {

// One line per problem, sorted: "msgid '{mass} at {speed}': translation names {masse}, {speed}".
std::vector<std::string> placeholderProblems(const Catalog& catalog);

}  // namespace collide::text
