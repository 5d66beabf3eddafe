# SPDX-License-Identifier: MIT
# Warning, sanitizer and floating-point flags applied to Lamina's own targets only.

set(LAMINA_WARNING_FLAGS -Wall -Wextra -Wpedantic -Wshadow -Wimplicit-fallthrough -Wformat=2
    -Wnon-virtual-dtor)
set(LAMINA_SANITIZE_FLAGS "")
if(LAMINA_SANITIZE)
  string(REPLACE ";" "," _lamina_sanitizers "${LAMINA_SANITIZE}")
  set(LAMINA_SANITIZE_FLAGS -fsanitize=${_lamina_sanitizers} -fno-sanitize-recover=all
      -fno-omit-frame-pointer)
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

# lamina_configure_target(TARGET): our warnings, -Werror in CI, sanitizers, reproducible FP, the
# debug information level (after the build type's -g, so that it wins).
function(lamina_configure_target target)
  target_compile_options(${target} PRIVATE ${LAMINA_WARNING_FLAGS} -ffp-contract=off
                         ${LAMINA_SANITIZE_FLAGS} ${LAMINA_DEBUG_INFO_FLAGS})
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
