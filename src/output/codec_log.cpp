#include "output/codec_log.hpp"

extern "C" {
#include <libavutil/log.h>
}

namespace collide::output {

void setCodecLogLevel(CodecLogLevel level) {
  switch (level) {
    case CodecLogLevel::kQuiet:
      av_log_set_level(AV_LOG_QUIET);
      break;
    case CodecLogLevel::kErrors:
      av_log_set_level(AV_LOG_ERROR);
      break;
    case CodecLogLevel::kWarnings:
      av_log_set_level(AV_LOG_WARNING);
      break;
    case CodecLogLevel::kVerbose:
      av_log_set_level(AV_LOG_INFO);
      break;
  }
}

}  // namespace collide::output
