# Run with cmake -P by the meshlab_prefix target (see MeshLabPrefix.cmake).
file(MAKE_DIRECTORY "${PREFIX}/bin" "${PLUGIN_DIR}")
# Copies, not symlinks: MeshLab finds its plugins relative to the real binary's path.
foreach(program IN ITEMS "${MESHLAB}" "${MESHLABSERVER}")  # no meshlabserver since 2021
  if(NOT program)
    continue()
  endif()
  file(COPY "${program}" DESTINATION "${PREFIX}/bin" FOLLOW_SYMLINK_CHAIN)
endforeach()
# libmeshlab-common.so (and 2022's libIFX*.so, 2025's libmeshlab-common-gui.so), found
# through $ORIGIN from bin/ and from the plugins.
file(GLOB libraries "${SYSTEM_DIR}/*.so")
foreach(library IN LISTS libraries)
  get_filename_component(name "${library}" NAME)
  file(CREATE_LINK "${library}" "${PLUGIN_DIR}/../${name}" SYMBOLIC)
endforeach()
file(GLOB stock_plugins "${SYSTEM_DIR}/plugins/*.so")
foreach(plugin IN LISTS stock_plugins)
  get_filename_component(name "${plugin}" NAME)
  if(NOT EXISTS "${PLUGIN_DIR}/${name}" OR IS_SYMLINK "${PLUGIN_DIR}/${name}")
    file(CREATE_LINK "${plugin}" "${PLUGIN_DIR}/${name}" SYMBOLIC)
  endif()
endforeach()
