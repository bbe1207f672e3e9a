#include <exception>
#include <iostream>

#include "app/cli.hpp"

int main(int argc, char** argv) {
  try {
    return collide::app::runCli(argc, argv, std::cout, std::cerr);
  } catch (const std::exception& e) {
    // Anything not mapped to a typed error is still a runtime failure with a message, never a
    // crash.
    std::cerr << "collide: internal error: " << e.what() << "\n";
    return 1;
  }
}
