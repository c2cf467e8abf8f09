# Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
# SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
#
# cmake -DBUILD_DIR=<build> -DTARGET=<target> -DEXPECTED=<text> -P expect_compile_error.cmake
# Passes when building TARGET fails AND the compiler's output contains EXPECTED
# (so the failure is the intended static_assert, not a broken setup).

execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" --target "${TARGET}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0)
  message(FATAL_ERROR "${TARGET} compiled, but it must not:\n${out}")
endif()
string(FIND "${out}" "${EXPECTED}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${TARGET} failed to compile, but without \"${EXPECTED}\":\n${out}")
endif()
message(STATUS "${TARGET} does not compile, as expected: \"${EXPECTED}\"")
