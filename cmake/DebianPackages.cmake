# Debian packages from this build tree, with CPack's DEB generator: `cpack -G DEB` in a
# build configured for /usr (scripts/make_packages.sh does both). One package per install
# component, named and split the Debian way:
#   meshlab-pcskeleton  (meshlab)  both plugins in MeshLab's plugin folder, meshlab-run for
#                                  MeshLab 2021+, the .mlx scripts in /usr/share/pcskeleton
#   pcskeleton          (cli)      the command-line tool and its man page
#   python3-pcskeleton  (python)   the module in /usr/lib/python3/dist-packages
#   libpcskeleton-dev   (dev)      the static library, its headers, the CMake package
# CPack rather than a debian/ folder: the packages come from the build the tests ran on,
# in seconds, with the version of project() and dpkg-shlibdeps' dependencies; a debian/
# folder would build everything a second time in each CI run.
set(PCSKELETON_DEB_REVISION 1 CACHE STRING "Debian revision of the packages")
set(PCSKELETON_DEB_MAINTAINER "pcskeleton developers <pcskeleton@users.noreply.github.com>" CACHE STRING
    "Maintainer field of the packages")

set(deb_components cli dev)
if(PCSKELETON_BUILD_PYTHON)
  list(APPEND deb_components python)
endif()
if(PCSKELETON_BUILD_PLUGINS)
  list(APPEND deb_components meshlab)
endif()

set(deb_name_cli pcskeleton)
set(deb_name_dev libpcskeleton-dev)
set(deb_name_python python3-pcskeleton)
set(deb_name_meshlab meshlab-pcskeleton)

# Each package's name, and its copyright and changelog where Debian looks for them.
foreach(component IN LISTS deb_components)
  set(package "${deb_name_${component}}")
  string(TOUPPER "${component}" c)
  set(CPACK_DEBIAN_${c}_PACKAGE_NAME "${package}")
  set(changelog "${PROJECT_BINARY_DIR}/packaging/${package}/changelog.Debian")
  string(TIMESTAMP date "%a, %d %b %Y %H:%M:%S +0000" UTC)
  file(WRITE "${changelog}"
    "${package} (${PROJECT_VERSION}-${PCSKELETON_DEB_REVISION}) unstable; urgency=medium\n\n"
    "  * Built from the pcskeleton source tree.\n\n"
    " -- ${PCSKELETON_DEB_MAINTAINER}  ${date}\n")
  execute_process(COMMAND gzip -9nf "${changelog}" RESULT_VARIABLE gzip_failed)
  if(gzip_failed)
    message(FATAL_ERROR "gzip could not compress ${changelog}")
  endif()
  install(FILES "${PROJECT_SOURCE_DIR}/packaging/copyright" "${changelog}.gz"
          DESTINATION "${CMAKE_INSTALL_DATADIR}/doc/${package}" COMPONENT ${component} EXCLUDE_FROM_ALL)
endforeach()

set(CPACK_PACKAGE_NAME pcskeleton)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_VENDOR "pcskeleton developers")
set(CPACK_PACKAGE_CONTACT "${PCSKELETON_DEB_MAINTAINER}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL ${deb_components})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE "${PCSKELETON_DEB_REVISION}")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_PACKAGE_DIRECTORY "${PROJECT_BINARY_DIR}/packages")

# CPack indents each line of a description by one space and an empty line becomes " .".
set(about "Curve skeletons of point clouds by Laplacian-based contraction (Cao,\nTagliasacchi, Olson, Zhang and Su, SMI 2010): a scan contracted and thinned\ninto a 1-D graph with a radius per node and a node per point, robust to\nnoise, outliers, missing data and one-sided scans; and a surface rebuilt\nto follow the skeleton.")

set(CPACK_COMPONENT_CLI_DESCRIPTION "curve skeletons of point clouds - command-line tool\n${about}\n\nThis package has the command-line tool pcskeleton.")
set(CPACK_COMPONENT_DEV_DESCRIPTION "curve skeletons of point clouds - C++ library\n${about}\n\nThis package has the static library, its headers and its CMake package:\nfind_package(pcskeleton CONFIG) gives the target pcskeleton::pcskeleton.")
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "libeigen3-dev (>= 3.3), libsuitesparse-dev, libgmp-dev")
set(CPACK_DEBIAN_DEV_PACKAGE_RECOMMENDS "cmake")

if(PCSKELETON_BUILD_PYTHON)
  set(CPACK_COMPONENT_PYTHON_DESCRIPTION "curve skeletons of point clouds - Python 3 module\n${about}\n\nThis package has the Python 3 module pcskeleton.")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_CONTROL_EXTRA
      "${PROJECT_SOURCE_DIR}/packaging/python3-pcskeleton/postinst;${PROJECT_SOURCE_DIR}/packaging/python3-pcskeleton/prerm")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_CONTROL_STRICT_PERMISSION ON)
  math(EXPR next_minor "${Python3_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
      "python3 (>= 3.${Python3_VERSION_MINOR}), python3 (<< 3.${next_minor}), python3-numpy")
endif()

if(PCSKELETON_BUILD_PLUGINS)
  set(CPACK_COMPONENT_MESHLAB_DESCRIPTION "curve skeletons of point clouds - MeshLab plugins\n${about}\n\nThis package has the MeshLab ${MESHLAB_VERSION} plugins: the filters (Compute\nCurve Skeleton, Reconstruct from Skeleton, Measure Skeleton Branches, ...)\nand the Edit Skeleton tool, with example .mlx scripts in\n/usr/share/pcskeleton/scripts.")
  set(CPACK_DEBIAN_MESHLAB_PACKAGE_SECTION graphics)
  # MeshLab loads only plugins built for its own version: this one, whatever the revision.
  string(REGEX REPLACE "^([0-9]+)\\.([0-9]+)$" "\\1" ml_year "${MESHLAB_VERSION}")
  string(REGEX REPLACE "^([0-9]+)\\.0?([0-9]+)$" "\\2" ml_month "${MESHLAB_VERSION}")
  math(EXPR ml_next "${ml_month} + 1")
  if(ml_next LESS 10)
    set(ml_next "0${ml_next}")
  endif()
  set(CPACK_DEBIAN_MESHLAB_PACKAGE_DEPENDS "meshlab (>= ${MESHLAB_VERSION}), meshlab (<< ${ml_year}.${ml_next})")
  # libmeshlab-common is MeshLab's private library, which the meshlab package itself provides.
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${MESHLAB_SYSTEM_DIR}")
endif()

include(CPack)
