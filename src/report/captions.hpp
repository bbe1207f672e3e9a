#pragma once
// Caption files from narration cues: WebVTT (the web's format, for <track> and most players) and
// SubRip (.srt, for older players and editors). Times are written to the millisecond.
#include <ostream>
#include <string>
#include <vector>

#include "report/narration.hpp"

namespace collide::report {

// "HH:MM:SS.mmm" (WebVTT) or "HH:MM:SS,mmm" (SRT) for `t_s` >= 0, rounded to the millisecond.
std::string captionTimestamp(double t_s, char decimal_separator);

// "WEBVTT - <title>", then one numbered cue per Cue. Cue text is escaped (&, <, >) and never
// holds "-->" or an empty line.
// With `language` (BCP 47), a "Language: de" header line (as YouTube and most caption tools read
// it; WebVTT parsers skip header lines).
void writeWebVtt(std::ostream& out, const std::vector<Cue>& cues, const std::string& title,
                 const std::string& language = "");

// Numbered SubRip cues separated by blank lines.
void writeSrt(std::ostream& out, const std::vector<Cue>& cues);

}  // namespace collide::report
