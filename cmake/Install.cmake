# What `cmake --install` puts where (GNUInstallDirs), and the manual pages it installs, built
# with the binary. Nothing installed refers back to the build or source tree: shaders and presets
# are compiled into the binary, fonts come from the fonts-dejavu-core package.
include(GNUInstallDirs)

find_program(COLLIDE_LOWDOWN lowdown)
if(NOT COLLIDE_LOWDOWN)
  message(FATAL_ERROR "lowdown not found (it writes the collide-scene(5) manual page): apt-get install lowdown")
endif()

set(COLLIDE_MAN_DIR ${PROJECT_BINARY_DIR}/man)
set(COLLIDE_SCENE_DOC ${PROJECT_SOURCE_DIR}/docs/scene-format.md)
add_custom_command(
  OUTPUT ${COLLIDE_MAN_DIR}/collide.1 ${COLLIDE_MAN_DIR}/collide.1.gz
         ${COLLIDE_MAN_DIR}/collide-scene.5 ${COLLIDE_MAN_DIR}/collide-scene.5.gz
  COMMAND ${CMAKE_COMMAND} -DCOLLIDE=$<TARGET_FILE:collide> -DLOWDOWN=${COLLIDE_LOWDOWN}
          -DSCENE_DOC=${COLLIDE_SCENE_DOC} -DOUT_DIR=${COLLIDE_MAN_DIR} -DVERSION=${PROJECT_VERSION}
          -P ${PROJECT_SOURCE_DIR}/cmake/GenerateManPages.cmake
  DEPENDS collide ${COLLIDE_SCENE_DOC} ${PROJECT_SOURCE_DIR}/cmake/GenerateManPages.cmake
  COMMENT "Writing the manual pages collide(1) and collide-scene(5)"
  VERBATIM)
add_custom_target(collide_man_pages ALL DEPENDS ${COLLIDE_MAN_DIR}/collide.1.gz
                                                ${COLLIDE_MAN_DIR}/collide-scene.5.gz)

install(TARGETS collide RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${COLLIDE_MAN_DIR}/collide.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${COLLIDE_MAN_DIR}/collide-scene.5.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man5)

# bash-completion loads completions/NAME when NAME is first completed.
install(FILES ${PROJECT_SOURCE_DIR}/completions/collide.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME collide)
# Debian's zsh reads vendor-completions for packages in /usr (the .deb); elsewhere (/usr/local, a
# shared prefix) site-functions is the directory zsh or the user puts in $fpath. Chosen at install
# time, because cpack installs with its own prefix.
install(CODE "
  set(zsh_dir site-functions)
  if(CMAKE_INSTALL_PREFIX MATCHES \"(^|/)usr/?$\")
    set(zsh_dir vendor-completions)
  endif()
  file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_DATADIR}/zsh/\${zsh_dir}\"
       TYPE FILE FILES \"${PROJECT_SOURCE_DIR}/completions/_collide\")")

# The guides, laid out as in the repository so the README's links keep working.
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        FILES_MATCHING PATTERN "*.md" PATTERN "*.png" PATTERN "*.svg")
