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

# Everyday use: sudo cmake --install build  (into Debian's MeshLab plugin directory).
install(TARGETS filter_pcskeleton edit_skeleton LIBRARY DESTINATION "${MESHLAB_SYSTEM_DIR}/plugins")
