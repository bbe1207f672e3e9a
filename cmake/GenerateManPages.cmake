# Run at build time (cmake -P) to write the manual pages into OUT_DIR, each also gzip'ed for
# installing:
#   collide.1        from `COLLIDE help-man`: the same command definitions that print --help;
#   collide-scene.5  from SCENE_DOC (docs/scene-format.md) through lowdown, the guide's own text.
# Inputs: COLLIDE, LOWDOWN, SCENE_DOC, OUT_DIR, VERSION.
foreach(input COLLIDE LOWDOWN SCENE_DOC OUT_DIR VERSION)
  if(NOT DEFINED ${input})
    message(FATAL_ERROR "GenerateManPages.cmake: ${input} not set")
  endif()
endforeach()
file(MAKE_DIRECTORY ${OUT_DIR})

# In a sanitizer build the binary is instrumented: a leak report at exit (the GL driver libraries
# are loaded even here) must not fail the build. The page itself is checked under LeakSanitizer by
# ManPageCliTest, with the suite's suppressions.
execute_process(COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=0 ${COLLIDE} help-man
                OUTPUT_FILE ${OUT_DIR}/collide.1 RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "'${COLLIDE} help-man' failed: ${status}")
endif()

# The guide's first heading is the page's title; its sections become the page's sections.
file(READ ${SCENE_DOC} guide)
string(REGEX REPLACE "^# [^\n]*\n" "" guide "${guide}")
string(REGEX REPLACE "\n## " "\n# " guide "${guide}")
string(REGEX REPLACE "\n### " "\n## " guide "${guide}")
file(WRITE ${OUT_DIR}/collide-scene.md "${guide}")
execute_process(COMMAND ${LOWDOWN} -Tman ${OUT_DIR}/collide-scene.md OUTPUT_VARIABLE body
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "lowdown failed on ${SCENE_DOC}: ${status}")
endif()
# Left-aligned and unhyphenated: the tables' narrow cells cannot be justified without warnings, and
# hyphens inside key names would mislead. Outside a UTF-8 locale (man's ASCII output) groff has no
# glyph for a superscript digit and would drop it with a warning ("one part in 10" for 10⁹): ^9.
set(superscripts "")
foreach(digit 0 4 5 6 7 8 9)
  string(APPEND superscripts ".char \\[u207${digit}] ^${digit}\n")
endforeach()
file(WRITE ${OUT_DIR}/collide-scene.5
  ".\\\" Generated from docs/scene-format.md by cmake/GenerateManPages.cmake. Do not edit.\n"
  ".TH COLLIDE-SCENE 5 \"\" \"collide ${VERSION}\" \"File Formats\"\n"
  ".ad l\n.nh\n"
  ".if !'\\*[.T]'utf8' \\{\\\n${superscripts}.char \\[u207B] ^-\n.\\}\n"
  ".SH NAME\n"
  "collide-scene \\- scene files for collide: bodies, walls, restitution and view, in TOML\n"
  ".SH DESCRIPTION\n"
  "${body}"
  ".SH SEE ALSO\n"
  "\\fBcollide\\fR(1)\n")

foreach(page collide.1 collide-scene.5)
  # -n: no name or time stamp inside, so the same page gives the same bytes.
  execute_process(COMMAND gzip -9nc ${OUT_DIR}/${page} OUTPUT_FILE ${OUT_DIR}/${page}.gz
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "gzip ${page} failed: ${status}")
  endif()
endforeach()
