# Compiler options shared by every Glint target, as one INTERFACE target
# (the pbrt-v4 `pbrt_warnings` pattern): link it, never set flags globally.
add_library(glint_options INTERFACE)
target_compile_options(glint_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow=local)
if(GLINT_NATIVE)
  target_compile_options(glint_options INTERFACE -march=native)
endif()
if(GLINT_SANITIZE)
  target_compile_options(glint_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(glint_options INTERFACE -fsanitize=address,undefined)
endif()
