# IVSHADOW_SANITIZE=ON builds everything with AddressSanitizer and UndefinedBehaviorSanitizer
# (a separate build directory; .ci/run runs the unit and GL suites in one). Reports stop the
# process (no recovery from undefined behaviour), so a test that triggers one fails.
# Runtime suppressions for libraries we do not build are in tests/sanitizers/.
option(IVSHADOW_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(IVSHADOW_SANITIZE)
  set(IVSHADOW_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=undefined
                               -fno-omit-frame-pointer)
  add_compile_options(${IVSHADOW_SANITIZER_FLAGS})
  add_link_options(${IVSHADOW_SANITIZER_FLAGS})
endif()

# IVSHADOW_FUZZ=ON (with clang) builds the libFuzzer harnesses of fuzz/: every source gets
# coverage instrumentation and the address and undefined-behaviour checks; bench/fuzz.sh
# configures such a build and runs each harness.
option(IVSHADOW_FUZZ "Build the libFuzzer harnesses (clang)" OFF)
if(IVSHADOW_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "IVSHADOW_FUZZ needs clang (CXX=clang++): libFuzzer is clang's")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
