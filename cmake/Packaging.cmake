# The .deb (scripts/package, or `cpack --config build/CPackConfig.cmake`). Its Depends come from the
# libraries that the binary and its modules (collide-video.so, collide-gl.so, collide-vector.so) link, found by
# dpkg-shlibdeps when the package is made, so a new dependency appears there without an edit here;
# only what the binary opens by name, not by linking, is listed: the DejaVu font, the DejaVu Math TeX
# Gyre font the working is typeset in (--working; fonts-dejavu-extra: without it the working falls
# back to plain text glyphs, no stretchy brackets or MATH constants), Mesa's EGL vendor library
# (GLVND's libEGL opens it) and the swrast DRI driver it opens in turn
# (tests/install/deb_package_test.sh finds both at run time).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME collide)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "collide")
set(CPACK_PACKAGE_CONTACT "collide maintainers <collide@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "exact collision simulations rendered as teaching videos and stills")
set(CPACK_PACKAGE_DESCRIPTION
    "collide turns a described collision into teaching material, headlessly: an exact,
event-driven simulation drives an OpenGL renderer on OSMesa or EGL (no display,
no GPU needed) that draws bodies, velocity arrows and an energy bar into MP4,
WebM, GIF, PNG stills and strobe pictures, with charts, captions and the numbers
as JSON or CSV. Scenes are presets or TOML files; batches spread over a cluster.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "fonts-dejavu-core, fonts-dejavu-extra, libegl-mesa0, libgl1-mesa-dri")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "bash-completion, zsh")
set(CPACK_SOURCE_GENERATOR "")
# cpack (and `make package`) install what is built; building is scripts/setup's job, and checking a
# large tree for staleness cost seconds per package.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
include(CPack)
