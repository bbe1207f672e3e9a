#pragma once

namespace collide::app {

// The tool's version, printed by --version and info, and written into file metadata. It comes from
// project(VERSION) in CMakeLists.txt, the same number the .deb carries.
#ifndef COLLIDE_VERSION
#error "COLLIDE_VERSION is defined by src/app/CMakeLists.txt from the project's version"
#endif
inline constexpr const char* kVersion = COLLIDE_VERSION;

}  // namespace collide::app
