#pragma once
// Writes a text result to a file (safely: temporary name, then rename) or to stdout for "-".
#include <functional>
#include <ostream>
#include <string>

namespace collide::app {

// While a StopSignals is held, a stop signal during `produce` (at a report's check point) or
// before the rename throws InterruptedError; the temporary file is removed and an earlier file at
// `path` stays as it was.
void writeTextOutput(const std::string& path, std::ostream& stdout_stream,
                     const std::function<void(std::ostream&)>& produce);

}  // namespace collide::app
