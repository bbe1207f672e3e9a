// Writes the argv fuzzer's seeds into DIR: for every command, each option its --help lists, given
// with a value of the kind the help names (after a preset as the scene), one file per option;
// the arguments are separated by NUL bytes (see argv_entry.hpp).
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"

namespace {

// A value of the kind --help shows after an option's name: "TEXT", "INT=60", "FLOAT", none.
std::string sampleValue(const std::string& name, const std::string& kind) {
  const std::size_t equals = kind.find('=');
  if (equals != std::string::npos) return kind.substr(equals + 1);  // the default
  if (name == "--set") return "restitution=0.3";
  if (name == "-o,--output") return "out.mp4";
  if (kind.rfind("INT", 0) == 0) return "2";
  if (kind.rfind("FLOAT", 0) == 0) return "1.5";
  return "x";
}

std::string help(const std::vector<const char*>& args) {
  std::vector<const char*> argv = {"collide"};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.push_back(nullptr);
  std::ostringstream out, err;
  collide::app::runCli(static_cast<int>(argv.size() - 1), argv.data(), out, err,
                       collide::app::CliMode::kParseOnly);
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_argv_seeds DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  int written = 0;
  const auto write = [&](const std::vector<std::string>& args) {
    std::ofstream file(dir + "/seed_" + std::to_string(written++));
    for (std::size_t i = 0; i < args.size(); ++i)
      file << (i > 0 ? std::string(1, '\0') : "") << args[i];
  };
  for (const char* command :
       {"render", "still", "strobe", "chart", "data", "presets", "check", "batch", "info"}) {
    struct Option {
      std::string name;   // the long name
      std::string value;  // empty for a flag
    };
    std::vector<Option> options, required;
    std::istringstream lines(help({command, "--help"}));
    for (std::string line; std::getline(lines, line);) {
      // Option lines: two spaces, a dash, the names, then the kind of value if any.
      if (line.rfind("  -", 0) != 0) continue;
      std::istringstream words(line);
      std::string names, kind;
      words >> names >> kind;
      if (names == "-h,--help") continue;
      const bool takes_value = !kind.empty() && kind[0] >= 'A' && kind[0] <= 'Z';
      Option option{names.substr(names.find(',') + 1), takes_value ? sampleValue(names, kind) : ""};
      (line.find(" REQUIRED ") != std::string::npos ? required : options).push_back(option);
    }
    // Each option once, beside what the command requires, so every seed parses.
    for (const Option& option : options) {
      std::vector<std::string> args = {command, "worked-example"};
      for (const Option* given : {&option}) {
        args.push_back(given->name);
        if (!given->value.empty()) args.push_back(given->value);
      }
      for (const Option& must : required) {
        args.push_back(must.name);
        if (!must.value.empty()) args.push_back(must.value);
      }
      write(args);
    }
  }
  write({"rendr", "worked-example"});
  write({"--version"});
  return 0;
}
