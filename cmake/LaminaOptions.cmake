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

# lamina_configure_target(TARGET): our warnings, -Werror in CI, sanitizers, reproducible FP.
function(lamina_configure_target target)
  target_compile_options(${target} PRIVATE ${LAMINA_WARNING_FLAGS} -ffp-contract=off
                         ${LAMINA_SANITIZE_FLAGS})
  if(LAMINA_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(LAMINA_SANITIZE_FLAGS)
    target_link_options(${target} PRIVATE ${LAMINA_SANITIZE_FLAGS})
  endif()
endfunction()
