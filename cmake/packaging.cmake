# SPDX-License-Identifier: GPL-3.0-or-later
# What is installed, and how it is split into Debian packages (`cpack -G DEB` in the build
# folder), so that a machine takes only what it uses: a headless server the command line without
# any GL, a C++ project the library and its headers, a Python user the module.
#
#   component  package         what                                         pulls in
#   cli        sculpt          bin/sculpt                                   CGAL's GMP and MPFR
#   render     sculpt-render   the headless rendering module (lib/sculpt)   OSMesa (llvmpipe)
#   library    libsculpt0      lib/libsculpt.so.0, the public API          GMP, MPFR
#   dev        libsculpt-dev   headers, libsculpt.so, CMake package         libsculpt0
#   python     python3-sculpt  the Python package                           python3, numpy
#   viewer     sculpt-view     bin/sculpt-view                              GLFW, OpenGL
#
# sculpt and python3-sculpt recommend sculpt-render: without it everything but pictures works,
# and a picture asked for says which package draws it. Every package carries Debian's
# copyright file in /usr/share/doc/PACKAGE.

install(TARGETS sculpt RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)
install(TARGETS sculpt_osmesa LIBRARY DESTINATION ${SCULPT_MODULE_INSTALL_DIR} COMPONENT render)
install(TARGETS sculpt_library EXPORT SculptTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT library NAMELINK_COMPONENT dev)
install(DIRECTORY include/sculpt DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev)
install(EXPORT SculptTargets NAMESPACE Sculpt:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Sculpt
        COMPONENT dev)
include(CMakePackageConfigHelpers)
configure_package_config_file(cmake/SculptConfig.cmake.in
  ${CMAKE_BINARY_DIR}/SculptConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Sculpt)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/SculptConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/SculptConfig.cmake ${CMAKE_BINARY_DIR}/SculptConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Sculpt COMPONENT dev)
set(SCULPT_COMPONENTS cli render library dev)
if(TARGET sculpt-view)
  install(TARGETS sculpt-view RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT viewer)
  list(APPEND SCULPT_COMPONENTS viewer)
endif()
if(SCULPT_BUILD_PYTHON)
  install(TARGETS sculpt_python LIBRARY DESTINATION ${SCULPT_PYTHON_INSTALL_DIR}/sculpt
          COMPONENT python)
  install(FILES ${SCULPT_PYTHON_SOURCES} DESTINATION ${SCULPT_PYTHON_INSTALL_DIR}/sculpt
          COMPONENT python)
  list(APPEND SCULPT_COMPONENTS python)
endif()

set(SCULPT_PACKAGE_cli sculpt)
set(SCULPT_PACKAGE_render sculpt-render)
set(SCULPT_PACKAGE_library libsculpt0)
set(SCULPT_PACKAGE_dev libsculpt-dev)
set(SCULPT_PACKAGE_python python3-sculpt)
set(SCULPT_PACKAGE_viewer sculpt-view)
foreach(component ${SCULPT_COMPONENTS})
  # Debian's machine-readable copyright file, where Debian policy puts it, and the licence.
  install(FILES packaging/copyright LICENSE
          DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/${SCULPT_PACKAGE_${component}}
          COMPONENT ${component})
  string(TOUPPER ${component} upper)
  set(CPACK_DEBIAN_${upper}_PACKAGE_NAME ${SCULPT_PACKAGE_${component}})
endforeach()

set(CPACK_PACKAGE_NAME sculpt)
set(CPACK_PACKAGE_VENDOR "Sculpt")
set(CPACK_PACKAGE_CONTACT "Sculpt developers <sculpt@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Delaunay-based curve and surface reconstruction by sculpting, and its peers")
set(CPACK_PACKAGE_DESCRIPTION
    "Sculpt reconstructs curves from 2D points and watertight surfaces from 3D points (Kuo & Yau "
    "2003, and the crust, co-cone, Advancing Front and alpha shapes), keeping every stage for "
    "inspection.")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL ${SCULPT_COMPONENTS})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS OFF)
set(CPACK_DEBIAN_LIBRARY_PACKAGE_SECTION libs)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "libsculpt0 (= ${PROJECT_VERSION})")
set(CPACK_DEBIAN_CLI_PACKAGE_RECOMMENDS "sculpt-render (= ${PROJECT_VERSION})")
set(CPACK_DEBIAN_VIEWER_PACKAGE_RECOMMENDS "sculpt (= ${PROJECT_VERSION})")
set(CPACK_COMPONENT_CLI_DESCRIPTION "the sculpt command: reconstruct, render, compare, bench")
set(CPACK_COMPONENT_RENDER_DESCRIPTION "headless rendering (OSMesa) for sculpt and python3-sculpt")
set(CPACK_COMPONENT_LIBRARY_DESCRIPTION "the reconstruction library libsculpt")
set(CPACK_COMPONENT_DEV_DESCRIPTION "headers and CMake package of libsculpt")
set(CPACK_COMPONENT_PYTHON_DESCRIPTION "the Python module sculpt")
set(CPACK_COMPONENT_VIEWER_DESCRIPTION "sculpt-view, the interactive viewer")
if(SCULPT_BUILD_PYTHON)
  math(EXPR next_minor "${Python3_VERSION_MINOR} + 1")  # the module is built for one version
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "python3 (>= ${SCULPT_PYTHON_VERSION}), \
python3 (<< ${Python3_VERSION_MAJOR}.${next_minor}), python3-numpy")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_RECOMMENDS "sculpt-render (= ${PROJECT_VERSION})")
endif()
include(CPack)
