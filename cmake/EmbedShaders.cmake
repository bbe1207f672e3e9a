# collide_embed_shaders(<output .cpp> <namespace> <shader files...>)
# Turns each GLSL file into a `const char* const <stem>_<ext>` string in the given namespace, so the
# binary needs no shader files at run time. Regenerated whenever a shader changes.
function(collide_embed_shaders output namespace)
  set(shader_files ${ARGN})
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DNAMESPACE=${namespace}
            "-DSHADERS=${shader_files}" -P ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    DEPENDS ${shader_files} ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    COMMENT "Embedding GLSL shaders into ${output}"
    VERBATIM)
endfunction()
