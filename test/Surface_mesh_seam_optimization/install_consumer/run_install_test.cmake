# Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
# SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
#
# cmake -DBUILD_DIR=<package build> -DWORK_DIR=<scratch> -DCONSUMER_DIR=<install_consumer>
#       -DMESH=<mesh> [-DCXX=<compiler>] -P run_install_test.cmake
# Installs the package from BUILD_DIR into WORK_DIR/prefix, then configures,
# builds and runs the consumer project against that prefix only.

foreach(var BUILD_DIR WORK_DIR CONSUMER_DIR MESH)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "${var} is not set")
  endif()
endforeach()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message(STATUS "${what}:\n${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc})")
  endif()
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
run_step("install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
if(NOT EXISTS "${prefix}/include/CGAL/Surface_mesh_seam_optimization/optimize_seams.h")
  message(FATAL_ERROR "the headers are not installed under ${prefix}/include")
endif()

set(compiler)
if(CXX)
  set(compiler "-DCMAKE_CXX_COMPILER=${CXX}")
endif()
run_step("configure the consumer" "${CMAKE_COMMAND}" -S "${CONSUMER_DIR}" -B "${WORK_DIR}/consumer"
         "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release ${compiler})
run_step("build the consumer" "${CMAKE_COMMAND}" --build "${WORK_DIR}/consumer")
run_step("run the consumer" "${WORK_DIR}/consumer/consumer" "${MESH}")
