#include "output/av_resources.hpp"

namespace collide::output::av {

void OutputFormatDeleter::operator()(AVFormatContext* context) const {
  if (context == nullptr) return;
  if (context->pb != nullptr && !(context->oformat->flags & AVFMT_NOFILE)) {
    avio_closep(&context->pb);
  }
  avformat_free_context(context);
}

std::string errorText(int av_error) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(av_error, text, sizeof text);
  return text;
}

std::string errorMessage(const std::string& what, const std::filesystem::path& path, int av_error) {
  return what + " '" + path.string() + "': " + errorText(av_error);
}

}  // namespace collide::output::av
