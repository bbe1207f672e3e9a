// SPDX-License-Identifier: MIT
#pragma once
// `collide lesson`'s page: one self-contained index.html that a teacher uploads as it is (a course
// page, a school site) or opens from disk. No script at all: the video with its captions as a
// <track default> in the page's language, a poster frame and the narration as a transcript; the
// stills and the stroboscope photograph with their alt text; the energy chart as SVG; the working
// as MathML when there is one; a table of the numbers and links to the data files. Its language
// sets lang and dir (Arabic reads right to left); its colours follow the reader's light or dark
// preference (prefers-color-scheme); it reads on a phone (nothing wider than 360 px).
//
// Chromium treats every file:// URL as an origin of its own and refuses a caption file beside the
// page, so the <track> carries the WebVTT text itself (a data: URL); the .vtt is linked for
// download and for players.
#include <string>
#include <vector>

#include "physics/timeline.hpp"

namespace collide::report {

struct LessonPicture {
  std::string file;  // beside index.html
  std::string alt;   // what it shows, for readers who cannot see it
  std::string caption;
  int width_px = 0, height_px = 0;
};

struct LessonLink {
  std::string file;
  std::string text;
};

struct LessonRow {
  std::string quantity;
  std::string value;
};

// Colours of one theme as CSS colours ("#1a1a1a").
struct LessonColors {
  std::string background, text, muted, rule, link;
};

struct LessonPage {
  std::string lang = "en";  // BCP 47
  bool right_to_left = false;
  std::string title;
  LessonColors light, dark;
  std::string video_mp4, video_webm, poster;  // files beside index.html
  int video_width_px = 0, video_height_px = 0;
  std::string captions_file;            // the .vtt beside index.html
  std::string captions_vtt;             // its text, carried by the <track> itself
  std::vector<std::string> transcript;  // the captions' cues, each one paragraph ('\n': a line)
  std::vector<LessonPicture> pictures;  // stills, strobe
  LessonPicture chart;                  // the energy chart (SVG); empty file: none
  std::string working_mathml;           // <math> elements; empty: none
  std::vector<LessonRow> numbers;
  std::vector<LessonLink> data;
};

// The page, words in the active language (text::activeLanguage()).
std::string lessonPageHtml(const LessonPage& page);

// One lesson in a batch's index page.
struct LessonEntry {
  std::string folder;  // relative to the index page, ending in '/'
  std::string title;
  LessonPicture poster;
};

// The index page of a batch's lessons: one link per lesson with its poster.
std::string lessonIndexHtml(const std::string& lang, bool right_to_left, const LessonColors& light,
                            const LessonColors& dark, const std::vector<LessonEntry>& lessons);

// The summary table: collisions, kinetic energy at the start and end, energy lost, total
// momentum at the start and end, in the active language's numbers.
std::vector<LessonRow> lessonNumbers(const physics::Timeline& timeline);

}  // namespace collide::report
