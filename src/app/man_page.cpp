#include "app/man_page.hpp"

#include <sstream>
#include <vector>

#include "app/version.hpp"

namespace collide::app {
namespace {

// A command is visible when `collide --help` lists it; hidden ones (group "") such as help-man
// itself stay out of the page as they stay out of --help.
std::vector<const CLI::App*> visibleSubcommands(const CLI::App& app) {
  return app.get_subcommands(
      [](const CLI::App* sub) { return !sub->get_group().empty() && !sub->get_name().empty(); });
}

std::string bold(const std::string& text) {
  return "\\fB" + roffEscape(text) + "\\fR";
}

// A footer or example block as --help prints it: indented lines (commands) kept as written in an
// indented block, other lines (prose, "Examples:") as text lines with a break after each.
std::string footerBlock(const std::string& text) {
  std::ostringstream out;
  out << ".PP\n";
  bool literal = false;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const bool indented = line.rfind("  ", 0) == 0;
    if (indented && !literal) out << ".RS 4\n.nf\n";
    if (!indented && literal) out << ".fi\n.RE\n";
    literal = indented;
    out << roffEscape(indented ? line.substr(2) : line) << "\n";
    if (!indented) out << ".br\n";
  }
  if (literal) out << ".fi\n.RE\n";
  return out.str();
}

// Text whose line breaks matter but whose lines may be filled: one roff line per source line,
// with a break between them.
std::string brokenLines(const std::string& text) {
  std::ostringstream out;
  std::istringstream lines(text);
  bool first = true;
  for (std::string line; std::getline(lines, line);) {
    if (!first) out << ".br\n";
    out << roffEscape(line) << "\n";
    first = false;
  }
  return out.str();
}

// CLI11's own help formatter with roff output: the option names, type names, defaults, groups and
// their order are computed by the base class exactly as for --help; only the layout differs.
class ManFormatter : public CLI::Formatter {
 public:
  std::string make_group(std::string group, bool is_positional,
                         std::vector<const CLI::Option*> opts) const override {
    std::ostringstream out;
    out << ".PP\n" << bold(group + ":") << "\n";
    for (const CLI::Option* opt : opts) out << make_option(opt, is_positional);
    return out.str();
  }

  std::string make_option(const CLI::Option* opt, bool is_positional) const override {
    // "-o,--output" becomes "-o, --output", each name bold; the type, default and REQUIRED italic.
    std::string names;
    std::istringstream split(make_option_name(opt, is_positional));
    for (std::string name; std::getline(split, name, ',');) {
      names += (names.empty() ? "" : ", ") + bold(name);
    }
    std::string details = make_option_opts(opt);
    if (!details.empty()) names += " \\fI" + roffEscape(details.substr(1)) + "\\fR";
    return ".TP\n" + names + "\n" + brokenLines(make_option_desc(opt));
  }

  std::string make_subcommand(const CLI::App* sub) const override {
    return ".TP\n" + bold(sub->get_name()) + "\n" + brokenLines(sub->get_description());
  }

  // What follows "Usage: NAME" in --help: "[OPTIONS] SCENE", "[OPTIONS] [SUBCOMMAND]".
  std::string usageArguments(const CLI::App* app) const {
    std::string usage = CLI::Formatter::make_usage(app, "");
    const std::string label = get_label("Usage") + ":";
    if (usage.rfind(label, 0) == 0) usage.erase(0, label.size());
    while (!usage.empty() && (usage.back() == '\n' || usage.back() == ' ')) usage.pop_back();
    while (!usage.empty() && usage.front() == ' ') usage.erase(0, 1);
    return usage;
  }

  // One command's section: what `collide COMMAND --help` prints, in the same order.
  std::string commandSection(const CLI::App* app, const std::string& path) const {
    std::ostringstream out;
    out << ".SS \"" << roffEscape(path + " " + usageArguments(app)) << "\"\n";
    out << brokenLines(app->get_description());
    out << make_positionals(app);
    out << make_groups(app, CLI::AppFormatMode::Normal);
    const std::vector<const CLI::App*> subs = visibleSubcommands(*app);
    if (!subs.empty()) {
      out << ".PP\n" << bold(get_label("Subcommands") + ":") << "\n";
      for (const CLI::App* sub : subs) out << make_subcommand(sub);
    }
    if (!app->get_footer().empty()) out << footerBlock(app->get_footer());
    for (const CLI::App* sub : subs) out << commandSection(sub, path + " " + sub->get_name());
    return out.str();
  }
};

std::string synopsis(const CLI::App& root, const ManFormatter& formatter) {
  std::ostringstream out;
  out << bold("collide") << " " << bold("--help") << " | " << bold("--version") << "\n";
  for (const CLI::App* sub : visibleSubcommands(root)) {
    out << ".br\n"
        << bold("collide " + sub->get_name()) << " " << roffEscape(formatter.usageArguments(sub))
        << "\n";
  }
  return out.str();
}

// The root description reads "collide: what it is"; NAME wants only "what it is".
std::string summary(const CLI::App& root) {
  std::string text = root.get_description();
  const std::string prefix = root.get_name() + ": ";
  if (text.rfind(prefix, 0) == 0) text.erase(0, prefix.size());
  return text;
}

}  // namespace

std::string roffEscape(const std::string& text) {
  std::string escaped;
  escaped.reserve(text.size() + text.size() / 8);
  for (char c : text) {
    if (c == '\\') {
      escaped += "\\e";
    } else if (c == '-') {
      escaped += "\\-";
    } else {
      escaped += c;
    }
  }
  // A line starting with '.' or '\'' would be a roff request; \& before it makes it text.
  std::string result;
  result.reserve(escaped.size());
  bool lineStart = true;
  for (char c : escaped) {
    if (lineStart && (c == '.' || c == '\'')) result += "\\&";
    result += c;
    lineStart = (c == '\n');
  }
  return result;
}

std::string manPage(const CLI::App& root) {
  ManFormatter formatter;
  std::ostringstream out;
  out << ".\\\" Generated by 'collide help-man' from the definitions behind --help. Do not edit.\n"
      << ".TH COLLIDE 1 \"\" \"collide " << kVersion << "\" \"User Commands\"\n"
      << ".ad l\n.nh\n"
      // Outside a UTF-8 locale (man's ASCII output) groff has no glyph for the language names in
      // their own scripts (--lang's help): it leaves them out there, without a warning for each.
      << ".if !'\\*[.T]'utf8' .warn (\\n[.warn] - (\\n[.warn] % 2))\n"
      << ".SH NAME\ncollide \\- " << roffEscape(summary(root)) << "\n"
      << ".SH SYNOPSIS\n"
      << synopsis(root, formatter)
      << ".SH DESCRIPTION\n"
         "collide turns a described collision into teaching material, headlessly. An exact, "
         "event\\-driven simulation (times of impact solved analytically, never by stepping) "
         "drives "
         "an OpenGL renderer on OSMesa or EGL (no display, no GPU needed) that draws the bodies, "
         "their velocity arrows and an energy bar into videos, stills, strobe pictures and charts; "
         "the numbers themselves come out as JSON or CSV.\n"
         ".PP\n"
         "A \\fISCENE\\fR is a preset name (\\fBcollide presets\\fR lists them) or a TOML scene "
         "file, described in \\fBcollide\\-scene\\fR(5). Any value of a scene can be changed from "
         "the "
         "command line with \\fB\\-\\-set\\fR \\fIKEY\\fR=\\fIVALUE\\fR.\n"
      << ".SH OPTIONS\n"
      << formatter.make_groups(&root, CLI::AppFormatMode::Normal) << ".SH COMMANDS\n";
  for (const CLI::App* sub : visibleSubcommands(root)) {
    out << formatter.commandSection(sub, "collide " + sub->get_name());
  }
  out << ".SH EXAMPLES\n"
      << footerBlock(root.get_footer())
      << ".SH EXIT STATUS\n"
         ".TP\n0\nSuccess.\n"
         ".TP\n1\nA runtime failure: GL context, encoder, disk, a write to standard output.\n"
         ".TP\n2\nBad usage or bad input; one line on standard error names where, the key, the "
         "value and what is allowed. Also an output that cannot be written, that is an input of "
         "the run or named twice, or that would exceed 10 GB or the free space without "
         "\\fB\\-\\-force\\fR, all found before any work.\n"
         ".TP\n130, 143, 129\nStopped by SIGINT, SIGTERM or SIGHUP (a run blocked on a FIFO or "
         "a stalled pipe ends 2 s after the signal).\n"
         ".PP\n"
         "Outputs are written under a temporary name and renamed when complete, so a failure or a "
         "signal never leaves a partial file at the output path.\n"
         ".SH ENVIRONMENT\n"
         ".TP\n.B COLLIDE_BACKEND\n"
         "The default GL backend: \\fBosmesa\\fR, \\fBegl\\fR, \\fBgpu\\fR or \\fBauto\\fR "
         "(\\fB\\-\\-backend\\fR overrides it).\n"
         ".SH FILES\n"
         ".TP\n.I /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf\n"
         "The font of every text unless \\fB\\-\\-font\\fR names another (package "
         "fonts\\-dejavu\\-core).\n"
         ".SH SEE ALSO\n"
         "\\fBcollide\\-scene\\fR(5); the guides in \\fIshare/doc/collide/\\fR under the "
         "installation prefix (\\fI/usr/share/doc/collide/\\fR from the .deb).\n";
  return out.str();
}

}  // namespace collide::app
