# Compiler options of Glint's own targets (library, CLI, tests, bench, examples), as one
# INTERFACE target (the pbrt-v4 `pbrt_warnings` pattern): each links it PRIVATE, never set
# flags globally. So warnings and -march=native never reach a program that links libglint.
add_library(glint_options INTERFACE)
target_compile_options(glint_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow=local)
if(GLINT_NATIVE)
  target_compile_options(glint_options INTERFACE -march=native)
endif()
if(GLINT_SANITIZE)
  target_compile_options(glint_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(glint_options INTERFACE -fsanitize=address,undefined)
endif()
if(GLINT_SANITIZE_THREAD)
  if(GLINT_SANITIZE)
    message(FATAL_ERROR "GLINT_SANITIZE_THREAD and GLINT_SANITIZE cannot be combined (one sanitizer runtime per program)")
  endif()
  target_compile_options(glint_options INTERFACE -fsanitize=thread -fno-omit-frame-pointer)
  target_link_options(glint_options INTERFACE -fsanitize=thread)
endif()
