# SPDX-License-Identifier: GPL-3.0-or-later
# Unpacks the CGAL meshes the tests read from Debian's libcgal-demo archive.
if(NOT EXISTS "${ARCHIVE}")
  message(FATAL_ERROR "${ARCHIVE} is missing: install Debian's libcgal-demo (scripts/install-dependencies)")
endif()
file(MAKE_DIRECTORY "${DESTINATION}")
execute_process(
  COMMAND ${CMAKE_COMMAND} -E tar xzf "${ARCHIVE}" data/meshes/bunny00.off data/meshes/knot1.off
          data/meshes/hand.off data/meshes/femur.off data/meshes/fandisk.off
          data/meshes/elephant.off data/meshes/refined_elephant.off data/meshes/armadillo.off
          data/meshes/holes.off data/meshes/mech-holes-shark.off
          data/meshes/cylinder_locally_refined.off data/meshes/oblong.off
          data/meshes/homer.off data/meshes/bull.off data/meshes/handle.off
          data/meshes/double-torus-example.off
  WORKING_DIRECTORY "${DESTINATION}"
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "could not unpack the CGAL meshes from ${ARCHIVE}")
endif()
