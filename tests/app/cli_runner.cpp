#include "cli_runner.hpp"

#include <sstream>

#include "app/cli.hpp"

namespace collide::test {

CliResult run(std::vector<std::string> args) {
  args.insert(args.begin(), "collide");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int code = app::runCli(static_cast<int>(argv.size()), argv.data(), out, err);
  return {code, out.str(), err.str()};
}

}  // namespace collide::test
