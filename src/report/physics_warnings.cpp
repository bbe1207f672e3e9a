#include "report/physics_warnings.hpp"

#include <map>
#include <ostream>

#include "core/typed_text.hpp"

namespace collide::report {

std::vector<std::string> physicsWarnings(const physics::Timeline& timeline,
                                         const std::string& context) {
  const std::string prefix = context.empty() ? "" : context + ": ";
  std::vector<std::string> lines;
  std::map<physics::WarningKind, int> seen;  // warnings of each kind so far
  int left_out = 0;
  for (const physics::Warning& warning : timeline.warnings()) {
    // A soft-contact scene can warn once per contact; a handful says what is wrong.
    if (++seen[warning.kind] > kWarningsPerKind) {
      ++left_out;
      continue;
    }
    lines.push_back(prefix + warning.message);
  }
  if (left_out > 0) {
    lines.push_back(prefix + std::to_string(left_out) + " more warning" +
                    (left_out == 1 ? "" : "s") + " like the above");
  }
  return lines;
}

void printWarnings(const std::vector<std::string>& warnings, std::ostream& err) {
  // Escaped: a body's name in a warning must not act on the terminal.
  for (const std::string& warning : warnings) {
    err << "warning: " << core::echoTyped(warning, 1000) << "\n";
  }
}

}  // namespace collide::report
