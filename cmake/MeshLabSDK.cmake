# MeshLab 2020.09's plugin headers come from Debian's source package (MESHLAB_SOURCE_DIR,
# set in the top-level CMakeLists.txt); the library is the installed one.
if(NOT EXISTS "${MESHLAB_SOURCE_DIR}/src/common/interfaces.h")
  message(FATAL_ERROR "MeshLab's plugin headers were not found in ${MESHLAB_SOURCE_DIR}.\n"
                      "Run scripts/setup.sh first (it installs the packages and unpacks them).")
endif()

set(MESHLAB_SYSTEM_DIR "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/meshlab" CACHE PATH
    "Where Debian's MeshLab keeps libmeshlab-common.so and its plugins")
find_library(MESHLAB_COMMON_LIBRARY meshlab-common PATHS "${MESHLAB_SYSTEM_DIR}" NO_DEFAULT_PATH REQUIRED)
find_program(MESHLAB_EXECUTABLE meshlab REQUIRED)
find_program(MESHLABSERVER_EXECUTABLE meshlabserver REQUIRED)

set(CMAKE_AUTOMOC ON)
find_package(Qt5 REQUIRED COMPONENTS Core Gui Widgets OpenGL Xml)
find_package(GLEW REQUIRED)

add_library(meshlab_sdk INTERFACE)
target_include_directories(meshlab_sdk SYSTEM INTERFACE
  "${MESHLAB_SOURCE_DIR}/src" "${MESHLAB_SOURCE_DIR}/vcglib")
# MeshLab's own build uses float meshes; a plugin compiled with double loads and crashes.
target_compile_definitions(meshlab_sdk INTERFACE MESHLAB_SCALAR=float)
target_link_libraries(meshlab_sdk INTERFACE
  "${MESHLAB_COMMON_LIBRARY}" Qt5::Core Qt5::Gui Qt5::Widgets Qt5::OpenGL Qt5::Xml GLEW::GLEW Eigen3::Eigen)
