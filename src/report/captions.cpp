#include "report/captions.hpp"

#include <cmath>
#include <cstdio>

namespace collide::report {
namespace {

// Cue text safe for both formats: no "-->" (it would read as a timing line), no blank lines (they
// end a cue), no carriage returns.
std::string cueSafe(const std::string& text) {
  std::string safe;
  for (const char c : text) {
    if (c == '\r') continue;
    if (c == '\n' && (safe.empty() || safe.back() == '\n')) continue;
    safe += c;
    if (safe.size() >= 3 && safe.compare(safe.size() - 3, 3, "-->") == 0) {
      safe.replace(safe.size() - 3, 3, "->");
    }
  }
  while (!safe.empty() && safe.back() == '\n') safe.pop_back();
  return safe.empty() ? "." : safe;
}

std::string escapeWebVtt(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

}  // namespace

std::string captionTimestamp(double t_s, char decimal_separator) {
  const long long ms = std::llround(std::max(0.0, t_s) * 1000.0);
  char text[40];
  std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld%c%03lld", ms / 3'600'000, ms / 60'000 % 60,
                ms / 1000 % 60, decimal_separator, ms % 1000);
  return text;
}

void writeWebVtt(std::ostream& out, const std::vector<Cue>& cues, const std::string& title,
                 const std::string& language) {
  out << "WEBVTT";
  std::string header = cueSafe(title);
  for (char& c : header) {
    if (c == '\n') c = ' ';
  }
  if (!title.empty()) out << " - " << header;
  out << "\n";
  if (!language.empty()) out << "Kind: captions\nLanguage: " << cueSafe(language) << "\n";
  int number = 1;
  for (const Cue& cue : cues) {
    out << "\n"
        << number++ << "\n"
        << captionTimestamp(cue.start_s, '.') << " --> " << captionTimestamp(cue.end_s, '.') << "\n"
        << escapeWebVtt(cueSafe(cue.text)) << "\n";
  }
}

void writeSrt(std::ostream& out, const std::vector<Cue>& cues) {
  int number = 1;
  for (const Cue& cue : cues) {
    if (number > 1) out << "\n";
    out << number++ << "\n"
        << captionTimestamp(cue.start_s, ',') << " --> " << captionTimestamp(cue.end_s, ',') << "\n"
        << cueSafe(cue.text) << "\n";
  }
}

}  // namespace collide::report
