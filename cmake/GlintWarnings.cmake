# Compiler options of Glint's own targets (library, CLI, tests, bench, examples), as one
# INTERFACE target (the pbrt-v4 `pbrt_warnings` pattern): each links it PRIVATE, never set
# flags globally. So warnings and -march=native never reach a program that links libglint.
add_library(glint_options INTERFACE)
target_compile_options(glint_options INTERFACE -Wall -Wextra -Wpedantic
                       $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local>)
if(GLINT_NATIVE)
  target_compile_options(glint_options INTERFACE -march=native)
endif()
if(GLINT_SANITIZE)
  target_compile_options(glint_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(glint_options INTERFACE -fsanitize=address,undefined)
endif()
if(GLINT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "GLINT_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  # Coverage instrumentation everywhere; only the fuzz targets link libFuzzer's main.
  # Undefined behaviour stops the run (a finding), as a crash does.
  target_compile_options(glint_options INTERFACE -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                         -fno-omit-frame-pointer)
  target_link_options(glint_options INTERFACE -fsanitize=address,undefined)
endif()
if(GLINT_SANITIZE_THREAD)
  if(GLINT_SANITIZE OR GLINT_FUZZ)
    message(FATAL_ERROR "GLINT_SANITIZE_THREAD cannot be combined with GLINT_SANITIZE or GLINT_FUZZ (one sanitizer runtime per program)")
  endif()
  target_compile_options(glint_options INTERFACE -fsanitize=thread -fno-omit-frame-pointer)
  target_link_options(glint_options INTERFACE -fsanitize=thread)
endif()
