#pragma once
// Writes a text result to a file (safely: temporary name, then rename) or to stdout for "-".
#include <functional>
#include <ostream>
#include <string>

namespace collide::app {

void writeTextOutput(const std::string& path, std::ostream& stdout_stream,
                     const std::function<void(std::ostream&)>& produce);

}  // namespace collide::app
