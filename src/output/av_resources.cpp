#include "output/av_resources.hpp"

#include "output/temp_file.hpp"

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
  // AVERROR(e) is -e for an errno value e; libav's own codes (FFERRTAG) are far more negative.
  constexpr int kLargestErrno = 4095;
  const bool is_errno = av_error < 0 && av_error >= -kLargestErrno;
  return what + " '" + path.string() + "': " + errorText(av_error) +
         (is_errno ? ioAdvice(-av_error) : std::string());
}

}  // namespace collide::output::av
