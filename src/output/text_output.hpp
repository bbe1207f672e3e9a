#pragma once
// Writes a text result or a finished document (an SVG, a PDF) to stdout for "-", or to a file
// through output::OutputFile: a regular file safely (temporary name, then rename), a device or FIFO
// in place.
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace collide::output {

// A stop request (core/stop_request.hpp: the app's SIGINT/SIGTERM handler) that arrives during the
// write (met at a report's check point inside `produce`, or before the rename) throws
// core::StopRequested; the temporary file is removed and an earlier file at `path` stays as it
// was. A stop that came before the call is the caller's to handle: batch still writes its manifest
// after one.
void writeTextOutput(const std::string& path, std::ostream& stdout_stream,
                     const std::function<void(std::ostream&)>& produce);

// Writes `bytes`, a whole document of kind `what` ("SVG", "PDF": for messages), to `path` ("-":
// stdout). Throws OutputError when the file cannot be created or written, core::StopRequested
// when a stop request arrived before the rename (the temporary file is removed).
void writeDocumentOutput(const std::string& path, std::string_view bytes, const std::string& what);

}  // namespace collide::output
