# One interface target carries the project's warnings and sanitizer flags; every ncsim target
# links it, so a flag is changed in exactly one place.
add_library(ncsim_options INTERFACE)
target_compile_options(ncsim_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                               -Wno-sign-conversion)
if(NCSIM_WERROR)
  target_compile_options(ncsim_options INTERFACE -Werror)
endif()
if(NCSIM_SANITIZE)
  target_compile_options(ncsim_options INTERFACE -fsanitize=address,undefined
                                                 -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(ncsim_options INTERFACE -fsanitize=address,undefined)
endif()
if(NCSIM_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "NCSIM_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++)")
  endif()
  target_compile_options(ncsim_options INTERFACE -fsanitize=fuzzer-no-link,address,undefined)
  target_link_options(ncsim_options INTERFACE -fsanitize=address,undefined)
endif()
