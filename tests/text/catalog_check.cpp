#include "catalog_check.hpp"

#include <algorithm>
#include <set>

#include "text/translate.hpp"

namespace collide::text {
namespace {

std::set<std::string> namesIn(const std::string& message) {
  const std::vector<std::string> names = placeholderNames(message);
  return {names.begin(), names.end()};
}

std::string listed(const std::set<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "{" : ", {") + name + "}";
  return out.empty() ? "none" : out;
}

}  // namespace

std::vector<std::string> placeholderProblems(const Catalog& catalog) {
  std::vector<std::string> problems;
  for (const Catalog::Entry& entry : catalog.entries()) {
    const std::string where = (entry.context.empty() ? "" : "context '" + entry.context + "', ") +
                              "msgid '" + entry.msgid + "'";
    if (entry.msgid_plural.empty()) {
      const std::set<std::string> want = namesIn(entry.msgid);
      const std::set<std::string> have = namesIn(entry.msgstrs.at(0));
      if (have != want) {
        problems.push_back(where + ": translation names " + listed(have) + ", the original " +
                           listed(want));
      }
      continue;
    }
    std::set<std::string> want = namesIn(entry.msgid_plural);
    want.merge(namesIn(entry.msgid));
    std::set<std::string> required = want;
    required.erase("count");
    for (std::size_t form = 0; form < entry.msgstrs.size(); ++form) {
      const std::set<std::string> have = namesIn(entry.msgstrs[form]);
      const bool extra = !std::includes(want.begin(), want.end(), have.begin(), have.end());
      const bool lacking =
          !std::includes(have.begin(), have.end(), required.begin(), required.end());
      if (extra || lacking) {
        problems.push_back(where + ": plural form " + std::to_string(form) + " names " +
                           listed(have) + ", the original " + listed(want) +
                           " (only {count} may be left out)");
      }
    }
  }
  std::sort(problems.begin(), problems.end());
  return problems;
}

}  // namespace collide::text
