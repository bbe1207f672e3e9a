// SPDX-License-Identifier: MIT
#include "report/lesson_page.hpp"

#include <cctype>
#include <sstream>

#include "core/markup.hpp"
#include "text/translate.hpp"

namespace collide::report {
namespace {

// RFC 4648 base64, for the captions' data: URL.
std::string base64(const std::string& bytes) {
  static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    unsigned value = static_cast<unsigned char>(bytes[i]) << 16;
    if (left > 1) value |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (left > 2) value |= static_cast<unsigned char>(bytes[i + 2]);
    out += kDigits[(value >> 18) & 63];
    out += kDigits[(value >> 12) & 63];
    out += left > 1 ? kDigits[(value >> 6) & 63] : '=';
    out += left > 2 ? kDigits[value & 63] : '=';
  }
  return out;
}

// A file name as a relative URL: every byte outside the unreserved set percent-encoded (a name
// with a space, '#' or '?' stays one file).
std::string fileUrl(const std::string& name) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string url;
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (std::isalnum(byte) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      url += c;
    } else {
      url += '%';
      url += kHex[byte >> 4];
      url += kHex[byte & 15];
    }
  }
  return url;
}

// The theme's colours and a layout that fits any width: nothing is wider than its column, long
// words and numbers break, the table scrolls inside itself if it must.
void writeStyle(std::ostream& out, const LessonColors& light, const LessonColors& dark) {
  const auto colors = [&out](const LessonColors& c) {
    out << "--bg:" << c.background << ";--fg:" << c.text << ";--muted:" << c.muted
        << ";--rule:" << c.rule << ";--link:" << c.link << ";";
  };
  out << "<style>\n:root{color-scheme:light dark;";
  colors(light);
  out << "}\n@media (prefers-color-scheme: dark){:root{";
  colors(dark);
  out << "}}\n"
         "*{box-sizing:border-box}\n"
         "body{margin:0;background:var(--bg);color:var(--fg);font:1rem/1.5 system-ui,"
         "'DejaVu Sans','Noto Sans',sans-serif;overflow-wrap:anywhere}\n"
         "header,main,footer{max-width:60rem;margin:0 auto;padding:0 1rem}\n"
         "a{color:var(--link)}\n"
         "h1{font-size:1.6rem;line-height:1.25}\n"
         "h2{font-size:1.25rem;border-top:1px solid var(--rule);padding-top:1rem}\n"
         "video,img{display:block;max-width:100%;height:auto;border:1px solid var(--rule)}\n"
         "figure{margin:1rem 0}\n"
         "figcaption,.muted{color:var(--muted)}\n"
         ".working-scroll{overflow-x:auto}\n"
         "math{font-size:1.15rem}\n"
         "table{border-collapse:collapse;width:100%}\n"
         "th,td{text-align:start;padding:.3rem .5rem;border-bottom:1px solid var(--rule)}\n"
         "</style>\n";
}

void writeHead(std::ostream& out, const std::string& lang, bool rtl, const std::string& title,
               const LessonColors& light, const LessonColors& dark) {
  out << "<!DOCTYPE html>\n<html lang=\"" << core::markupEscaped(lang) << "\" dir=\""
      << (rtl ? "rtl" : "ltr") << "\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<meta name=\"generator\" content=\"collide\">\n"
      << "<title>" << core::markupEscaped(title) << "</title>\n";
  writeStyle(out, light, dark);
  out << "</head>\n<body>\n";
}

void writeFigure(std::ostream& out, const LessonPicture& picture) {
  out << "<figure>\n<img src=\"" << fileUrl(picture.file) << "\" alt=\""
      << core::markupEscaped(picture.alt) << "\" width=\"" << picture.width_px << "\" height=\""
      << picture.height_px << "\">\n";
  if (!picture.caption.empty()) {
    out << "<figcaption>" << core::markupEscaped(picture.caption) << "</figcaption>\n";
  }
  out << "</figure>\n";
}

// One paragraph per cue, its lines kept.
void writeTranscript(std::ostream& out, const std::vector<std::string>& cues) {
  for (const std::string& cue : cues) {
    std::string html = core::markupEscaped(cue);
    const std::string line_break = "<br>\n";
    for (std::size_t at = html.find('\n'); at != std::string::npos;
         at = html.find('\n', at + line_break.size())) {
      html.replace(at, 1, line_break);
    }
    out << "<p>" << html << "</p>\n";
  }
}

void writeVideo(std::ostream& out, const LessonPage& page) {
  // TRANSLATORS: a heading of the lesson page (collide lesson): the video.
  out << "<section aria-labelledby=\"video\">\n<h2 id=\"video\">"
      << core::markupEscaped(text::trc("lesson page", "Video"))
      << "</h2>\n<video controls preload=\"auto\" poster=\"" << fileUrl(page.poster)
      << "\" width=\"" << page.video_width_px << "\" height=\"" << page.video_height_px << "\">\n"
      << "<source src=\"" << fileUrl(page.video_mp4) << "\" type=\"video/mp4\">\n"
      << "<source src=\"" << fileUrl(page.video_webm) << "\" type=\"video/webm\">\n"
      << "<track kind=\"captions\" srclang=\"" << core::markupEscaped(page.lang) << "\" label=\""
      << core::markupEscaped(text::tr("Narration")) << "\" src=\"data:text/vtt;base64,"
      << base64(page.captions_vtt) << "\" default>\n"
      << "<a href=\"" << fileUrl(page.video_mp4) << "\">" << core::markupEscaped(page.video_mp4)
      << "</a>\n</video>\n";
  // TRANSLATORS: a heading of the lesson page: the narration of the video as text.
  out << "<h3>" << core::markupEscaped(text::trc("lesson page", "Transcript")) << "</h3>\n";
  writeTranscript(out, page.transcript);
  out << "</section>\n";
}

void writeNumbers(std::ostream& out, const LessonPage& page) {
  // TRANSLATORS: a heading of the lesson page: the table of the simulation's numbers and the
  // data files.
  out << "<section aria-labelledby=\"numbers\">\n<h2 id=\"numbers\">"
      << core::markupEscaped(text::trc("lesson page", "Numbers"))
      << "</h2>\n<table>\n<thead><tr><th scope=\"col\">"
      // TRANSLATORS: a column of the lesson page's table of numbers.
      << core::markupEscaped(text::trc("lesson page", "Quantity"))
      << "</th><th scope=\"col\">"
      // TRANSLATORS: a column of the lesson page's table of numbers.
      << core::markupEscaped(text::trc("lesson page", "Value")) << "</th></tr></thead>\n<tbody>\n";
  for (const LessonRow& row : page.numbers) {
    out << "<tr><th scope=\"row\">" << core::markupEscaped(row.quantity) << "</th><td>"
        << core::markupEscaped(row.value) << "</td></tr>\n";
  }
  out << "</tbody>\n</table>\n<ul>\n";
  for (const LessonLink& link : page.data) {
    out << "<li><a href=\"" << fileUrl(link.file) << "\">" << core::markupEscaped(link.text)
        << "</a> <span class=\"muted\">(" << core::markupEscaped(link.file) << ")</span></li>\n";
  }
  out << "</ul>\n</section>\n";
}

}  // namespace

std::string lessonPageHtml(const LessonPage& page) {
  std::ostringstream out;
  writeHead(out, page.lang, page.right_to_left, page.title, page.light, page.dark);
  out << "<header>\n<h1>" << core::markupEscaped(page.title) << "</h1>\n</header>\n<main>\n";
  writeVideo(out, page);
  // TRANSLATORS: a heading of the lesson page: the stills, the stroboscope photograph, the chart.
  out << "<section aria-labelledby=\"pictures\">\n<h2 id=\"pictures\">"
      << core::markupEscaped(text::trc("lesson page", "Pictures")) << "</h2>\n";
  for (const LessonPicture& picture : page.pictures) writeFigure(out, picture);
  if (!page.chart.file.empty()) writeFigure(out, page.chart);
  out << "</section>\n";
  if (!page.working_mathml.empty()) {
    // TRANSLATORS: a heading of the lesson page: the worked solution, step by step.
    out << "<section aria-labelledby=\"working\">\n<h2 id=\"working\">"
        << core::markupEscaped(text::trc("lesson page", "Working"))
        << "</h2>\n<div class=\"working-scroll\" tabindex=\"0\" role=\"group\" "
           "aria-labelledby=\"working\">\n"
        << page.working_mathml << "\n</div>\n</section>\n";
  }
  writeNumbers(out, page);
  out << "</main>\n<footer>\n<p class=\"muted\">collide</p>\n</footer>\n</body>\n</html>\n";
  return out.str();
}

std::string lessonIndexHtml(const std::string& lang, bool right_to_left, const LessonColors& light,
                            const LessonColors& dark, const std::vector<LessonEntry>& lessons) {
  std::ostringstream out;
  // TRANSLATORS: the title of a batch's index page of lessons (collide batch --formats lesson).
  const std::string title = text::trc("lesson page", "Lessons");
  writeHead(out, lang, right_to_left, title, light, dark);
  out << "<header>\n<h1>" << core::markupEscaped(title) << "</h1>\n</header>\n<main>\n<ul>\n";
  for (const LessonEntry& lesson : lessons) {
    out << "<li>\n<h2><a href=\"" << fileUrl(lesson.folder) << "index.html\">"
        << core::markupEscaped(lesson.title) << "</a></h2>\n";
    LessonPicture poster = lesson.poster;
    poster.file = lesson.folder + poster.file;
    writeFigure(out, poster);
    out << "</li>\n";
  }
  out << "</ul>\n</main>\n</body>\n</html>\n";
  return out.str();
}

}  // namespace collide::report
