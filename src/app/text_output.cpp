#include "app/text_output.hpp"

#include <cerrno>
#include <fstream>

#include "output/frame_sink.hpp"
#include "output/temp_file.hpp"

namespace collide::app {

void writeTextOutput(const std::string& path, std::ostream& stdout_stream,
                     const std::function<void(std::ostream&)>& produce) {
  if (path == "-") {
    produce(stdout_stream);
    stdout_stream.flush();
    return;
  }
  output::TemporaryFile file(path);
  std::ofstream stream(file.path(), std::ios::binary);
  if (!stream) throw output::OutputError(output::ioErrorMessage("cannot create", path, errno));
  errno = 0;
  produce(stream);
  // close() writes what is still buffered, so a full disk may only show here; checked before the
  // rename, so a short file never replaces the target.
  stream.close();
  if (!stream) {
    throw output::OutputError(
        output::ioErrorMessage("cannot write", path, errno != 0 ? errno : EIO));
  }
  file.commit();
}

}  // namespace collide::app
