# One interface target carries the project's warnings and sanitizer flags; every ncsim target
# links it, so a flag is changed in exactly one place.
add_library(ncsim_options INTERFACE)
target_compile_options(ncsim_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                               -Wno-sign-conversion)
# g++ 12 reports false -Wrestrict positives inside std::string concatenation at -O3 (GCC bug
# 105329, fixed in 13); off for those versions so Release builds keep -Werror.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(ncsim_options INTERFACE -Wno-restrict)
endif()
if(NCSIM_WERROR)
  target_compile_options(ncsim_options INTERFACE -Werror)
endif()
# -fsanitize=undefined leaves out float-cast-overflow (a double beyond the range of the integer
# it is converted to: G04 1e17 became a 0 s dwell unseen, issue 34 item 1); it is added here.
# float-divide-by-zero is not (yet): a floating division by zero gives inf or NaN (IEEE 754),
# which ncsim catches where results leave it (NC4101 in expressions, NC6302 for a setpoint,
# null in JSON), and tests/cli/hostile_property_test.sh checks that no NaN or infinity reaches an
# output; whether the flag finds more is left for a session with a full sanitizer run to spare.
set(NCSIM_UBSAN "undefined,float-cast-overflow")
if(NCSIM_SANITIZE)
  target_compile_options(ncsim_options INTERFACE -fsanitize=address,${NCSIM_UBSAN}
                                                 -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(ncsim_options INTERFACE -fsanitize=address,${NCSIM_UBSAN})
endif()
if(NCSIM_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "NCSIM_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++)")
  endif()
  target_compile_options(ncsim_options INTERFACE -fsanitize=fuzzer-no-link,address,${NCSIM_UBSAN})
  target_link_options(ncsim_options INTERFACE -fsanitize=address,${NCSIM_UBSAN})
endif()
# ncsim_small_memset(TARGET): GCC on x86-64 zero-fills a value type of known size (the jerk
# kernel's Move 216 bytes, Reversal 432, a Level, a Profile 848) with `rep stosq`, whose
# start-up cost was ~7 % of a time-optimal PTP plan (issue 36, docs/axes-profile.md "Thirteenth
# round"); vector stores instead up to 1 KiB, memset() above. Results are unchanged (no
# arithmetic is touched); other compilers and targets keep their defaults.
function(ncsim_small_memset target)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
    target_compile_options(${target} PRIVATE
                           "-mmemset-strategy=vector_loop:1024:noalign,libcall:-1:noalign")
  endif()
endfunction()
