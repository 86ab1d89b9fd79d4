# MeshLab's plugin headers come from its source tree (MESHLAB_SOURCE_DIR and MESHLAB_VERSION,
# set in the top-level CMakeLists.txt); the library is the installed one, of the same version.
if(PCSKELETON_MESHLAB_VERSION GREATER_EQUAL 202105)
  set(MESHLAB_PLUGIN_HEADER "${MESHLAB_SOURCE_DIR}/src/common/plugins/interfaces/filter_plugin.h")
else()
  set(MESHLAB_PLUGIN_HEADER "${MESHLAB_SOURCE_DIR}/src/common/interfaces.h")
endif()
if(NOT EXISTS "${MESHLAB_PLUGIN_HEADER}")
  message(FATAL_ERROR "MeshLab's plugin headers were not found in ${MESHLAB_SOURCE_DIR}.\n"
                      "Run scripts/setup.sh first (it installs the packages and unpacks them).")
endif()

set(MESHLAB_SYSTEM_DIR "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/meshlab" CACHE PATH
    "Where Debian's MeshLab keeps libmeshlab-common.so and its plugins")
find_library(MESHLAB_COMMON_LIBRARY meshlab-common PATHS "${MESHLAB_SYSTEM_DIR}" NO_DEFAULT_PATH REQUIRED)
find_program(MESHLAB_EXECUTABLE meshlab REQUIRED)
if(PCSKELETON_MESHLAB_VERSION LESS 202105)
  find_program(MESHLABSERVER_EXECUTABLE meshlabserver REQUIRED)  # gone since 2021.06
endif()

set(CMAKE_AUTOMOC ON)
find_package(Qt5 REQUIRED COMPONENTS Core Gui Widgets OpenGL Xml)
find_package(GLEW REQUIRED)

add_library(meshlab_sdk INTERFACE)
target_include_directories(meshlab_sdk SYSTEM INTERFACE
  "${MESHLAB_SOURCE_DIR}/src" "${VCGLIB_DIR}")
# MeshLab's own build uses float meshes; a plugin compiled with double loads and crashes.
# From 2021 on MeshLab refuses a plugin built for another version or precision: the
# version it checks is MESHLAB_VERSION, compiled into the plugin.
target_compile_definitions(meshlab_sdk INTERFACE MESHLAB_SCALAR=float
  PCSKELETON_MESHLAB_VERSION=${PCSKELETON_MESHLAB_VERSION})
if(PCSKELETON_MESHLAB_VERSION GREATER_EQUAL 202105)
  target_compile_definitions(meshlab_sdk INTERFACE MESHLAB_VERSION=${MESHLAB_VERSION})
endif()
target_link_libraries(meshlab_sdk INTERFACE
  "${MESHLAB_COMMON_LIBRARY}" Qt5::Core Qt5::Gui Qt5::Widgets Qt5::OpenGL Qt5::Xml GLEW::GLEW Eigen3::Eigen)
