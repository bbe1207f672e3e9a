#pragma once

namespace collide::app {

// The tool's version, printed by --version and info, and written into file metadata.
inline constexpr const char* kVersion = "0.1.0";

}  // namespace collide::app
