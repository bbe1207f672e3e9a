#pragma once
// How much libavcodec/libavformat/libx264 print to stderr. Their log level is process-wide, so
// sinks never change it; the app sets it once at start-up (quiet unless asked to be verbose).
namespace collide::output {

enum class CodecLogLevel {
  kQuiet,     // nothing
  kErrors,    // errors only: the right default for a CLI, which reports failures itself
  kWarnings,  // errors and warnings
  kVerbose,   // libav's normal chatter: encoder settings, per-frame-type statistics
};

void setCodecLogLevel(CodecLogLevel level);

}  // namespace collide::output
