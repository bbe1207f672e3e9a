# Finds every third-party dependency; a missing one stops CMake with the Debian package to install.
find_package(PkgConfig)
if(NOT PKG_CONFIG_FOUND)
  message(FATAL_ERROR "pkg-config not found: apt-get install pkg-config")
endif()

# collide_require_pkg(<target-name> <pkg-config module> <debian package>)
function(collide_require_pkg name module debian_package)
  pkg_check_modules(${name} QUIET IMPORTED_TARGET GLOBAL ${module})
  if(NOT ${name}_FOUND)
    message(FATAL_ERROR "${module} not found: apt-get install ${debian_package}")
  endif()
endfunction()

# GL backends. OSMesa (the default backend) was removed from Mesa 25.1, so it is optional: AUTO
# builds it when found. EGL (surfaceless, and devices for GPUs) is always built.
set(COLLIDE_WITH_OSMESA AUTO CACHE STRING "Build the OSMesa backend: ON, OFF or AUTO (when found)")
set_property(CACHE COLLIDE_WITH_OSMESA PROPERTY STRINGS ON OFF AUTO)
set(COLLIDE_HAVE_OSMESA OFF)
if(NOT COLLIDE_WITH_OSMESA STREQUAL "OFF")
  pkg_check_modules(OSMESA QUIET IMPORTED_TARGET GLOBAL osmesa)
  if(OSMESA_FOUND)
    set(COLLIDE_HAVE_OSMESA ON)
  elseif(COLLIDE_WITH_OSMESA STREQUAL "ON")
    message(FATAL_ERROR "osmesa not found: apt-get install libosmesa6-dev (or -DCOLLIDE_WITH_OSMESA=OFF)")
  endif()
endif()
message(STATUS "collide: OSMesa backend ${COLLIDE_HAVE_OSMESA}")
collide_require_pkg(EGL egl libegl-dev)
if(NOT COLLIDE_HAVE_OSMESA)
  # Without libOSMesa's gl* exports, the GL entry points come from GLVND's libOpenGL.
  collide_require_pkg(OPENGL opengl libopengl-dev)
endif()
collide_require_pkg(PNG libpng libpng-dev)
# A large PNG still is deflated in parts with zlib itself (output/png_deflate.hpp).
collide_require_pkg(ZLIB zlib zlib1g-dev)
collide_require_pkg(AVCODEC libavcodec libavcodec-dev)
collide_require_pkg(AVFORMAT libavformat libavformat-dev)
collide_require_pkg(AVUTIL libavutil libavutil-dev)
collide_require_pkg(SWSCALE libswscale libswscale-dev)
collide_require_pkg(FREETYPE freetype2 libfreetype-dev)
# Text in every script: shaping, bidirectional order, a font per script.
collide_require_pkg(HARFBUZZ harfbuzz libharfbuzz-dev)
collide_require_pkg(FRIBIDI fribidi libfribidi-dev)
collide_require_pkg(FONTCONFIG fontconfig libfontconfig-dev)
collide_require_pkg(CAIRO cairo libcairo2-dev)
# Scene values with arithmetic ("2/3") and units ("60 km/h"): muParser and UDUNITS-2 (no .pc file).
collide_require_pkg(MUPARSER muparser libmuparser-dev)
find_path(UDUNITS2_INCLUDE_DIR udunits2.h)
find_library(UDUNITS2_LIBRARY udunits2)
if(NOT UDUNITS2_INCLUDE_DIR OR NOT UDUNITS2_LIBRARY)
  message(FATAL_ERROR "UDUNITS-2 not found: apt-get install libudunits2-dev")
endif()

find_package(Eigen3 3.3 QUIET NO_MODULE)
if(NOT TARGET Eigen3::Eigen)
  message(FATAL_ERROR "Eigen3 not found: apt-get install libeigen3-dev")
endif()

find_path(TOMLPP_INCLUDE_DIR toml++/toml.h)
if(NOT TOMLPP_INCLUDE_DIR)
  message(FATAL_ERROR "toml++ not found: apt-get install libtomlplusplus-dev")
endif()

find_path(BOOST_MATH_INCLUDE_DIR boost/math/special_functions/jacobi_elliptic.hpp)
if(NOT BOOST_MATH_INCLUDE_DIR)
  message(FATAL_ERROR "Boost.Math not found: apt-get install libboost-math-dev")
endif()

# JSON read back: `collide batch --merge` reads the shards' manifests; tests read every JSON output.
find_package(nlohmann_json 3.10 QUIET)
if(NOT TARGET nlohmann_json::nlohmann_json)
  message(FATAL_ERROR "nlohmann-json not found: apt-get install nlohmann-json3-dev")
endif()

find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp)
if(NOT CLI11_INCLUDE_DIR)
  message(FATAL_ERROR "CLI11 not found: apt-get install libcli11-dev")
endif()

if(BUILD_TESTING OR NOT DEFINED BUILD_TESTING)
  # Tests read the SVG figures back as XML.
  collide_require_pkg(LIBXML2 libxml-2.0 libxml2-dev)
  find_package(GTest QUIET)
  if(NOT GTest_FOUND)
    message(FATAL_ERROR "GoogleTest not found: apt-get install libgtest-dev")
  endif()
endif()
