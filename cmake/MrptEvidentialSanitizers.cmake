# Sanitizer and fuzzing builds (doc/reliability.md). The flags go to every
# target of the project, so that the library and what calls it agree; MRPT and
# the other system libraries stay as Debian built them.
set(MRPT_EVIDENTIAL_SANITIZE "" CACHE STRING
  "Sanitizers to build with, e.g. address,undefined or thread (empty: none)")
option(MRPT_EVIDENTIAL_BUILD_FUZZERS "Build the libFuzzer targets (clang only)" OFF)
option(MRPT_EVIDENTIAL_RELIABILITY_TESTS
  "Add the tests that build and run the sanitizer and fuzzing trees (normal builds only)" ON)
set(MRPT_EVIDENTIAL_FUZZ_SECONDS 30 CACHE STRING
  "How long each fuzzer runs in its CTest test")

if(MRPT_EVIDENTIAL_SANITIZE)
  # Any finding stops the program, so that a test cannot pass with one.
  # Line tables only (-g1): the reports' file and line, for less build time
  # than full debug information.
  add_compile_options(-fsanitize=${MRPT_EVIDENTIAL_SANITIZE}
    -fno-sanitize-recover=all -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=${MRPT_EVIDENTIAL_SANITIZE})
endif()

if(MRPT_EVIDENTIAL_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "MRPT_EVIDENTIAL_BUILD_FUZZERS needs clang "
      "(-DCMAKE_CXX_COMPILER=clang++), not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  # Coverage for libFuzzer everywhere; only the fuzz targets link its main.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
