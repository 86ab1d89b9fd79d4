# A private MeshLab inside the build tree: copies of Debian's meshlab/meshlabserver in
# build/meshlab/bin load plugins from build/meshlab/lib/<arch>/meshlab/plugins, where the
# stock plugins are linked and ours are built. Nothing outside the build tree is touched.
set(MESHLAB_PREFIX "${PROJECT_BINARY_DIR}/meshlab")
set(MESHLAB_PREFIX_PLUGIN_DIR "${MESHLAB_PREFIX}/lib/${CMAKE_LIBRARY_ARCHITECTURE}/meshlab/plugins")

add_custom_target(meshlab_prefix ALL
  COMMAND "${CMAKE_COMMAND}"
          -DPREFIX=${MESHLAB_PREFIX}
          -DPLUGIN_DIR=${MESHLAB_PREFIX_PLUGIN_DIR}
          -DSYSTEM_DIR=${MESHLAB_SYSTEM_DIR}
          -DMESHLAB=${MESHLAB_EXECUTABLE}
          -DMESHLABSERVER=${MESHLABSERVER_EXECUTABLE}
          -P "${PROJECT_SOURCE_DIR}/cmake/make_meshlab_prefix.cmake"
  COMMENT "Setting up the MeshLab prefix in ${MESHLAB_PREFIX}"
  VERBATIM)

# Everyday use: sudo cmake --install build  (into Debian's MeshLab plugin directory, the
# only one MeshLab loads system plugins from, whatever the prefix: the component `meshlab`;
# the others, `cli`, `python` and `dev`, go under the prefix).
install(TARGETS filter_pcskeleton edit_skeleton LIBRARY DESTINATION "${MESHLAB_SYSTEM_DIR}/plugins" COMPONENT meshlab)

# Without root, MeshLab 2021+ only: cmake --install build-2022 --component user-plugins
# puts the plugins in MeshLab's per-user plugin folder, read when the installing user runs
# it: $XDG_DATA_HOME (or ~/.local/share)/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/<version>,
# and meshlab-run in ~/.local/bin.
if(PCSKELETON_MESHLAB_VERSION GREATER_EQUAL 202105)
  install(CODE "
    set(data_home \"\$ENV{XDG_DATA_HOME}\")
    if(data_home STREQUAL \"\")
      set(data_home \"\$ENV{HOME}/.local/share\")
    endif()
    file(INSTALL \"$<TARGET_FILE:filter_pcskeleton>\" \"$<TARGET_FILE:edit_skeleton>\"
         DESTINATION \"\${data_home}/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/${MESHLAB_VERSION}\" USE_SOURCE_PERMISSIONS)
    file(INSTALL \"$<TARGET_FILE:meshlab-run>\" DESTINATION \"\$ENV{HOME}/.local/bin\" USE_SOURCE_PERMISSIONS)
  " COMPONENT user-plugins EXCLUDE_FROM_ALL)
endif()
