#include "output/text_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "core/stop_request.hpp"
#include "output/frame_sink.hpp"
#include "output/output_file.hpp"
#include "output/temp_file.hpp"

namespace collide::output {
namespace {

// Runs `produce`; a stop request met inside it (a report's check point) becomes an
// StopRequested saying what became of the output, `consequence`.
void produceUnlessStopped(const std::function<void(std::ostream&)>& produce, std::ostream& stream,
                          const std::string& consequence) {
  try {
    produce(stream);
  } catch (const core::StopRequested& stop) {
    if (stop.saysWhatBecameOfTheOutput()) throw;
    throw core::StopRequested(stop.signalNumber(), consequence);
  }
}

// Runs `produce` into `stream` and flushes it. The first write that fails (a full disk or device,
// a closed descriptor, a reader that went away while SIGPIPE is ignored) ends it at once with
// OutputError "cannot write <shown>: <why>", instead of producing the rest into a dead stream.
void produceChecked(const std::function<void(std::ostream&)>& produce, std::ostream& stream,
                    const std::string& consequence, const std::string& shown) {
  const std::ios::iostate old_exceptions = stream.exceptions();
  errno = 0;
  try {
    stream.exceptions(std::ios::badbit);
    produceUnlessStopped(produce, stream, consequence);
    stream.flush();
  } catch (const std::ios_base::failure&) {
    // The failed write(2) set errno; nothing between it and here calls into the system.
    const int error_number = errno != 0 ? errno : EIO;
    // Left bad: nothing more goes to it. The mask goes back first (setting it rethrows).
    stream.exceptions(old_exceptions & ~std::ios::badbit);
    throw OutputError("cannot write " + shown + ": " + std::strerror(error_number) +
                      ioAdvice(error_number));
  }
  stream.exceptions(old_exceptions);
}

}  // namespace

void writeTextOutput(const std::string& path, std::ostream& stdout_stream,
                     const std::function<void(std::ostream&)>& produce) {
  if (path == "-") {
    // Bytes already on stdout cannot be taken back; the message says the text is cut short.
    produceChecked(produce, stdout_stream, "the output on stdout is incomplete", "to stdout");
    return;
  }
  // A stop requested before this write began was seen by the caller, which writes this file
  // anyway: batch's manifest, listing the jobs the stop cut short. Only a stop during it counts.
  const bool stop_already_seen = core::stopRequested() != 0;
  // A regular file is replaced through a temporary file; a device or FIFO is written in place.
  output::OutputFile file(path);
  std::ofstream stream(file.writePath(), std::ios::binary);
  if (!stream) throw output::OutputError(output::ioErrorMessage("cannot create", path, errno));
  const std::string removed = "file '" + path + "'";
  produceChecked(produce, stream, "removed the partly written " + removed, "'" + path + "'");
  // close() writes what is still buffered, so a full disk may only show here; checked before the
  // rename, so a short file never replaces the target.
  errno = 0;
  stream.close();
  if (!stream) {
    throw output::OutputError(
        output::ioErrorMessage("cannot write", path, errno != 0 ? errno : EIO));
  }
  // The last chance to keep the earlier file: a signal during the writing stops here at the
  // latest (the OutputFile removes what was written).
  if (!stop_already_seen) {
    if (const int signal_number = core::stopRequested(); signal_number != 0) {
      throw core::StopRequested(signal_number, "removed the partly written " + removed);
    }
  }
  file.commit();
}

void writeDocumentOutput(const std::string& path, std::string_view bytes, const std::string& what) {
  // A regular file via a temporary name and a rename; a device or FIFO in place; "-" is stdout.
  OutputFile file(path);
  const bool to_stdout = file.writePath() == kStdoutName;
  std::FILE* out = to_stdout ? stdout : std::fopen(file.writePath().c_str(), "wb");
  if (out == nullptr) {
    throw OutputError(ioErrorMessage("cannot create " + what, path, errno));
  }
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size();
  const int write_errno = errno;
  const bool closed = to_stdout ? std::fflush(out) == 0 : std::fclose(out) == 0;
  if (!written || !closed) {
    throw OutputError(ioErrorMessage("cannot write " + what, path, !written ? write_errno : errno));
  }
  if (const int signal_number = core::stopRequested(); signal_number != 0) {
    throw core::StopRequested(signal_number,
                              "removed the partly written " + what + " '" + path + "'");
  }
  file.commit();
}

}  // namespace collide::output
