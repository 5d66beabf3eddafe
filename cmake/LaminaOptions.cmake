# SPDX-License-Identifier: MIT
# Warning, sanitizer and floating-point flags applied to Lamina's own targets only.

set(LAMINA_WARNING_FLAGS -Wall -Wextra -Wpedantic -Wshadow -Wimplicit-fallthrough -Wformat=2
    -Wnon-virtual-dtor)
set(LAMINA_SANITIZE_FLAGS "")
set(LAMINA_SANITIZE_COMPILE_FLAGS "")
if(LAMINA_SANITIZE)
  string(REPLACE ";" "," _lamina_sanitizers "${LAMINA_SANITIZE}")
  set(LAMINA_SANITIZE_FLAGS -fsanitize=${_lamina_sanitizers} -fno-sanitize-recover=all
      -fno-omit-frame-pointer)
  # -O1, as AddressSanitizer's documentation advises: Eigen and the contact code at -O0 made the
  # sanitizer tests 7x slower (383 s against 51 s for `make test-asan`'s 880 tests on the 2-core
  # CI machine; the build takes 100 s more). Assertions stay on (no NDEBUG); -g keeps file:line.
  set(LAMINA_SANITIZE_COMPILE_FLAGS -O1)
endif()

# How much debug information the build types that carry it (RelWithDebInfo, Debug) get: "full"
# (-g, the default), "lines" (-g1: file:line in backtraces and sanitizer reports, no variables;
# CI uses it: a third less compile time — tests/unit/primitive_contacts_test.cpp takes 28 s
# with -g, 19 s with -g1 on the CI machine) or "none" (-g0). The code generated is the same.
set(LAMINA_DEBUG_INFO "full" CACHE STRING "Debug information: full, lines or none")
set_property(CACHE LAMINA_DEBUG_INFO PROPERTY STRINGS full lines none)
set(LAMINA_DEBUG_INFO_FLAGS "")
if(LAMINA_DEBUG_INFO STREQUAL "lines")
  set(LAMINA_DEBUG_INFO_FLAGS -g1)
elseif(LAMINA_DEBUG_INFO STREQUAL "none")
  set(LAMINA_DEBUG_INFO_FLAGS -g0)
elseif(NOT LAMINA_DEBUG_INFO STREQUAL "full")
  message(FATAL_ERROR "LAMINA_DEBUG_INFO must be full, lines or none, got '${LAMINA_DEBUG_INFO}'")
endif()

# lamina_configure_target(TARGET [TEST]): our warnings, -Werror in CI, sanitizers, reproducible
# FP, the debug information level (after the build type's -g, so that it wins). TEST: a test
# executable or the test support library, compiled without the sanitizers' instrumentation but
# linked with their runtime. The sanitizers check Lamina's libraries, which the tests drive (and
# the headers those compile); instrumenting GoogleTest's templates in the test files themselves
# doubled their compile time (primitive_contacts_test.cpp: 34 s against 17 s; 685 s of the CI
# machine's CPU for the 79 test files, about 3 minutes of a CI run on two cores).
function(lamina_configure_target target)
  set(sanitize_compile ${LAMINA_SANITIZE_FLAGS})
  if("TEST" IN_LIST ARGN AND LAMINA_SANITIZE_FLAGS)
    # Eigen allocates with its own aligned malloc where __SANITIZE_ADDRESS__ is defined and with
    # malloc elsewhere: a matrix made in one kind of file and freed in the other would be freed
    # the wrong way, so the test files take the instrumented files' choice
    set(sanitize_compile -fno-omit-frame-pointer -DEIGEN_MALLOC_ALREADY_ALIGNED=0)
  endif()
  # -fno-semantic-interposition: with the Python module on, the core is compiled as position-
  # independent code, and GCC then treats every function with external linkage as one a shared
  # object loaded first could replace, so it inlines none into another, not even within a unity
  # batch. Nothing in Lamina is meant to be interposed.
  target_compile_options(${target} PRIVATE ${LAMINA_WARNING_FLAGS} -ffp-contract=off
                         -fno-semantic-interposition ${sanitize_compile}
                         ${LAMINA_SANITIZE_COMPILE_FLAGS} ${LAMINA_DEBUG_INFO_FLAGS})
  if(LAMINA_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(LAMINA_SANITIZE_FLAGS)
    target_link_options(${target} PRIVATE ${LAMINA_SANITIZE_FLAGS})
  endif()
endfunction()

# lld links each test executable (which carries the whole core and its debug information) in
# 0.5 s instead of GNU ld's 3 s (5 s instead of 1.5 s under the sanitizers): minutes of every CI
# run. The code is the same; only the linker differs. GNU ld when lld is missing or turned off.
if(LAMINA_USE_LLD)
  include(CheckLinkerFlag)
  check_linker_flag(CXX "-fuse-ld=lld" LAMINA_HAVE_LLD)
  if(LAMINA_HAVE_LLD)
    add_link_options(-fuse-ld=lld)
  endif()
endif()

# Precompiled headers: every core source includes Eigen through core/math_types.h and every test
# GoogleTest; parsing them took about 1.1 s of each file's 1.5-2.5 s (measured on
# core/sim/sleep.cpp: 2.3 s, 1.1 s with the header precompiled). lamina_core precompiles its
# own; the tests share one, built by lamina_test_support (REUSE_FROM needs equal flags, which
# lamina_configure_target gives every test). The code generated is the same; only parsing moves.
set(LAMINA_PCH_STD_HEADERS <algorithm> <array> <cmath> <functional> <map> <memory> <optional>
    <string> <utility> <vector>)
set(LAMINA_PCH_CORE_HEADERS ${LAMINA_PCH_STD_HEADERS} <Eigen/Core> <Eigen/Geometry>)
set(LAMINA_PCH_TEST_HEADERS ${LAMINA_PCH_CORE_HEADERS} <gtest/gtest.h> <gmock/gmock.h>)

#
# GCC 12 loses the system-header mark of code that comes from a precompiled header, so its
# optimizer's flow warnings about inlined standard-library and Eigen code (the known false
# positives of -Warray-bounds, -Wstringop-overflow/-overread and -Wmaybe-uninitialized on
# std::string and Eigen::Transform, which it stays silent about without the header) reach our
# files. With precompiled headers those four stay warnings, printed, but do not fail a -Werror
# build; configure with -DLAMINA_PRECOMPILED_HEADERS=OFF to have them as errors again.
set(LAMINA_PCH_FLAGS "")
if(LAMINA_PRECOMPILED_HEADERS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  set(LAMINA_PCH_FLAGS -Wno-error=array-bounds -Wno-error=stringop-overflow
      -Wno-error=stringop-overread -Wno-error=maybe-uninitialized)
endif()

# lamina_precompile(TARGET HEADERS...): precompile HEADERS for TARGET when the option is on
function(lamina_precompile target)
  if(LAMINA_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE ${ARGN})
    target_compile_options(${target} PRIVATE ${LAMINA_PCH_FLAGS})
  endif()
endfunction()

# lamina_reuse_test_pch(TARGET): a test executable uses lamina_test_support's precompiled header
function(lamina_reuse_test_pch target)
  if(LAMINA_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} REUSE_FROM lamina_test_support)
    target_compile_options(${target} PRIVATE ${LAMINA_PCH_FLAGS})
  endif()
endfunction()

# lamina_unity(TARGET): TARGET's sources compile in unity batches of 8 files, one translation
# unit a batch, when LAMINA_UNITY_BUILD is on. Each file instantiated and optimized the same
# Eigen, standard-library and GoogleTest templates again: 6 unit test files took 29 s apart and
# 16 s as one, 8 files of core/sim 25 s apart and 11 s as one. A fresh-clone CI run on the
# 2-core machine took 1699 s without batches and 1041 s with them; with the test areas alone in
# batches, 1633 s, of which the optimized build 774 s and the sanitizer build 599 s (425 s and
# 378 s with the core in batches too). The code is the same (inlining across a batch's files
# aside; floating point keeps -ffp-contract=off). The files of a batch share their anonymous
# namespace, so a name at namespace scope must be unique within the target.
function(lamina_unity target)
  if(LAMINA_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
endfunction()
