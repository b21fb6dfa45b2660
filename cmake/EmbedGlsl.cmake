# Embeds GLSL sources into a generated C++ header at build time, so shaders live in .glsl
# files but ship inside the library. Each file becomes
#   inline constexpr const char* k<Name> = R"glsl(...)glsl";
# where <Name> is the file name in CamelCase without dots (dsm_build.frag -> kDsmBuildFrag). A
# line #include "part.glsl" in a file is replaced by that file of its folder; list the parts
# too, so that changing one embeds again.

set(IVSHADOW_EMBED_GLSL_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/EmbedGlslScript.cmake)

function(ivshadow_embed_glsl target header)
  set(sources ${ARGN})
  set(output ${CMAKE_CURRENT_BINARY_DIR}/generated/${header})
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} "-DSOURCES=${sources}"
            -P ${IVSHADOW_EMBED_GLSL_SCRIPT}
    DEPENDS ${sources} ${IVSHADOW_EMBED_GLSL_SCRIPT}
    COMMENT "Embedding GLSL sources into ${header}"
    VERBATIM)
  target_sources(${target} PRIVATE ${output})
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)
endfunction()
