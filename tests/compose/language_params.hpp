#pragma once
// The parameters of a test run once per shipped language (TextFitLanguageTest,
// LayoutKeepsTextTest): every language's tag, and a gtest name made of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "text/language.hpp"

namespace collide::test {

inline std::vector<std::string> languageTags() {
  std::vector<std::string> tags;
  for (const text::Language& language : text::shippedLanguages()) tags.push_back(language.tag);
  return tags;
}

// "pt-BR" as "pt_BR": gtest names take letters, digits and underscores.
inline std::string languageName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

}  // namespace collide::test
