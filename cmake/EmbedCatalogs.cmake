# collide_embed_catalogs(<output .cpp> <function> <po files...>)
# Compiles each po/<tag>.po with msgfmt --check (fuzzy entries left out, as gettext does) and
# embeds the MO bytes in the generated .cpp as collide::text::detail::<function>() (the shipped
# catalogues are embeddedCatalogs(), text/embedded_catalogs.hpp), so the binary reads no catalogue
# from an install path. Regenerated whenever a PO file changes.
find_program(COLLIDE_MSGFMT msgfmt)
if(NOT COLLIDE_MSGFMT)
  message(FATAL_ERROR "msgfmt not found: apt-get install gettext")
endif()

function(collide_embed_catalogs output function)
  set(mo_files "")
  set(tags "")
  foreach(po IN LISTS ARGN)
    get_filename_component(stem ${po} NAME_WE)
    string(REPLACE "_" "-" tag ${stem})
    set(mo ${CMAKE_CURRENT_BINARY_DIR}/${function}/${stem}.mo)
    add_custom_command(
      OUTPUT ${mo}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_CURRENT_BINARY_DIR}/${function}
      COMMAND ${COLLIDE_MSGFMT} --check -o ${mo} ${po}
      DEPENDS ${po}
      COMMENT "Compiling the ${tag} catalogue"
      VERBATIM)
    list(APPEND mo_files ${mo})
    list(APPEND tags ${tag})
  endforeach()
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DFUNCTION=${function} "-DTAGS=${tags}" "-DMO_FILES=${mo_files}" -P
            ${PROJECT_SOURCE_DIR}/cmake/EmbedCatalogsScript.cmake
    DEPENDS ${mo_files} ${PROJECT_SOURCE_DIR}/cmake/EmbedCatalogsScript.cmake
    COMMENT "Embedding the message catalogues into ${output}"
    VERBATIM)
endfunction()
