# brdfbake_add_tables(TARGET <name> SCENE <file> OUTPUT_DIR <dir> [DEPENDS <files>...])
#
# Bakes the BRDF tables a scene needs (a brdfbake TOML manifest, or a glTF .gltf/.glb file) into
# OUTPUT_DIR at build time, as the target <name> (part of ALL). The bake runs when the scene file,
# the extra DEPENDS or the brdfbake binary change; an unchanged scene costs nothing (the stamp
# file is up to date), and brdfbake itself rewrites only the tables whose content hash changed.
# The stamp, ${CMAKE_CURRENT_BINARY_DIR}/<name>.brdfbake-stamp, lists the tables of the last bake,
# one absolute path per line; the target's BRDFBAKE_STAMP and BRDFBAKE_OUTPUT_DIR properties name
# it and the directory.
#
# Works with find_package(brdfbake) (the installed, imported brdfbake::brdfbake) and with
# add_subdirectory(<brdfbake source>) (the brdfbake target built in the same build).
function(brdfbake_add_tables)
  cmake_parse_arguments(ARG "" "TARGET;SCENE;OUTPUT_DIR" "DEPENDS" ${ARGN})
  foreach(required TARGET SCENE OUTPUT_DIR)
    if(NOT ARG_${required})
      message(FATAL_ERROR "brdfbake_add_tables: ${required} is required "
                          "(brdfbake_add_tables(TARGET name SCENE file OUTPUT_DIR dir))")
    endif()
  endforeach()
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "brdfbake_add_tables: unexpected arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET brdfbake::brdfbake)
    message(FATAL_ERROR "brdfbake_add_tables: no brdfbake::brdfbake target "
                        "(find_package(brdfbake) or add_subdirectory(brdfbake) first)")
  endif()
  get_filename_component(scene "${ARG_SCENE}" ABSOLUTE)
  if(NOT EXISTS "${scene}")
    message(FATAL_ERROR "brdfbake_add_tables: SCENE ${scene} does not exist")
  endif()
  get_filename_component(outdir "${ARG_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  set(stamp "${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}.brdfbake-stamp")
  # the baker: a file dependency when imported, a target (built first) when built here
  get_target_property(aliased brdfbake::brdfbake ALIASED_TARGET)
  if(aliased)
    set(baker ${aliased})
  else()
    set(baker "$<TARGET_FILE:brdfbake::brdfbake>")
  endif()
  add_custom_command(
    OUTPUT "${stamp}"
    COMMAND brdfbake::brdfbake bake "${scene}" -o "${outdir}" --stamp "${stamp}"
    DEPENDS "${scene}" ${baker} ${ARG_DEPENDS}
    COMMENT "brdfbake: baking the tables of ${ARG_SCENE}"
    VERBATIM)
  add_custom_target(${ARG_TARGET} ALL DEPENDS "${stamp}")
  set_target_properties(${ARG_TARGET} PROPERTIES BRDFBAKE_STAMP "${stamp}" BRDFBAKE_OUTPUT_DIR "${outdir}")
endfunction()
