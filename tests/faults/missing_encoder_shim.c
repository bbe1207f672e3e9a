// LD_PRELOAD fault: video encoders that this libavcodec "lacks". Every encoder named in
// COLLIDE_FAULT_ENCODERS (comma-separated libavcodec names, e.g. "libx264,libvpx-vp9,gif") is
// reported missing, as by a libavcodec built without it; the others are found as usual.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <libavcodec/avcodec.h>

#include "fault_list.h"

static const AVCodec* unlessHidden(const AVCodec* codec) {
  if (codec != NULL && faultListHas("COLLIDE_FAULT_ENCODERS", codec->name)) return NULL;
  return codec;
}

const AVCodec* avcodec_find_encoder_by_name(const char* name) {
  typedef const AVCodec* (*Real)(const char*);
  Real real;
  COLLIDE_FAULT_NEXT(real, "avcodec_find_encoder_by_name");
  return unlessHidden(real(name));
}

const AVCodec* avcodec_find_encoder(enum AVCodecID id) {
  typedef const AVCodec* (*Real)(enum AVCodecID);
  Real real;
  COLLIDE_FAULT_NEXT(real, "avcodec_find_encoder");
  return unlessHidden(real(id));
}
