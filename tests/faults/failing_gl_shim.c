// LD_PRELOAD fault: GL contexts that cannot be created. COLLIDE_FAULT_GL lists the backends that
// fail: "osmesa" (OSMesaCreateContextAttribs/Ext return NULL, as when libOSMesa cannot give a
// core context) and "egl" (eglInitialize fails, as when no EGL driver loads; this covers both the
// surfaceless and the GPU device backends). Unlisted backends work as usual.
#define _GNU_SOURCE
#include <EGL/egl.h>
#include <dlfcn.h>

#include "fault_list.h"

// OSMesa's prototypes, declared here so the shim builds where OSMesa's headers are missing.
// OSMesaContext is an opaque pointer.
typedef void* OpaqueOsmesaContext;

OpaqueOsmesaContext OSMesaCreateContextAttribs(const int* attributes, OpaqueOsmesaContext share) {
  if (faultListHas("COLLIDE_FAULT_GL", "osmesa")) return NULL;
  typedef OpaqueOsmesaContext (*Real)(const int*, OpaqueOsmesaContext);
  Real real;
  COLLIDE_FAULT_NEXT(real, "OSMesaCreateContextAttribs");
  return real != NULL ? real(attributes, share) : NULL;
}

OpaqueOsmesaContext OSMesaCreateContextExt(unsigned format, int depth_bits, int stencil_bits,
                                           int accum_bits, OpaqueOsmesaContext share) {
  if (faultListHas("COLLIDE_FAULT_GL", "osmesa")) return NULL;
  typedef OpaqueOsmesaContext (*Real)(unsigned, int, int, int, OpaqueOsmesaContext);
  Real real;
  COLLIDE_FAULT_NEXT(real, "OSMesaCreateContextExt");
  return real != NULL ? real(format, depth_bits, stencil_bits, accum_bits, share) : NULL;
}

EGLBoolean eglInitialize(EGLDisplay display, EGLint* major, EGLint* minor) {
  if (faultListHas("COLLIDE_FAULT_GL", "egl")) return EGL_FALSE;
  typedef EGLBoolean (*Real)(EGLDisplay, EGLint*, EGLint*);
  Real real;
  COLLIDE_FAULT_NEXT(real, "eglInitialize");
  return real != NULL ? real(display, major, minor) : EGL_FALSE;
}
