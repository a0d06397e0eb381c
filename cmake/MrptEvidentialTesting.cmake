# How the project declares its tests. Every test runs under
# tests/support/memory_budget, which records its peak resident memory in
# test-memory/ of the build tree and fails a test that peaks above its budget
# (doc/reliability.md). scripts/quickstart.sh prints the ten largest peaks.
if(MRPT_EVIDENTIAL_SANITIZE)
  set(default_budget 6144)  # sanitizers' shadow memory and quarantine
else()
  set(default_budget 2048)
endif()
set(MRPT_EVIDENTIAL_TEST_MEMORY_BUDGET_MB ${default_budget} CACHE STRING
  "Largest peak resident memory of a test, MB")
set(MRPT_EVIDENTIAL_SANITIZER_MEMORY_BUDGET_MB 6144 CACHE STRING
  "Largest peak resident memory of the tests that build or run the sanitizer trees, MB")
set(MRPT_EVIDENTIAL_TEST_PEAKS_DIR ${PROJECT_BINARY_DIR}/test-memory)
file(MAKE_DIRECTORY ${MRPT_EVIDENTIAL_TEST_PEAKS_DIR})

# The launcher's command line, up to and including "--".
function(mrpt_evidential_budget_launcher out budget)
  set(${out} ${PROJECT_BINARY_DIR}/tests/support/memory_budget
    --record ${MRPT_EVIDENTIAL_TEST_PEAKS_DIR} --budget-mb ${budget} -- PARENT_SCOPE)
endfunction()

# mrpt_evidential_add_test(NAME COMMAND cmd args... [BUDGET_MB mb])
# add_test() under the memory budget. The command's program is a path or a
# generator expression (a target name is not resolved after the launcher).
function(mrpt_evidential_add_test name)
  cmake_parse_arguments(arg "" "BUDGET_MB" "COMMAND" ${ARGN})
  if(NOT arg_BUDGET_MB)
    set(arg_BUDGET_MB ${MRPT_EVIDENTIAL_TEST_MEMORY_BUDGET_MB})
  endif()
  mrpt_evidential_budget_launcher(launcher ${arg_BUDGET_MB})
  list(INSERT launcher 1 --name ${name})
  add_test(NAME ${name} COMMAND ${launcher} ${arg_COMMAND})
endfunction()

# mrpt_evidential_add_suite(NAME SOURCES a.cpp... LIBRARIES lib... [TEST_PREFIX p])
# One GoogleTest executable, its tests discovered into CTest with label
# "unit" (their names prefixed with p, if given) and run under the memory
# budget. The target unit_suites builds them all (the sanitizer tree builds
# nothing else of the tests).
add_custom_target(unit_suites)
function(mrpt_evidential_add_suite name)
  cmake_parse_arguments(arg "" "TEST_PREFIX" "SOURCES;LIBRARIES" ${ARGN})
  add_executable(${name} ${arg_SOURCES})
  target_link_libraries(${name} PRIVATE ${arg_LIBRARIES} GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    MRPT_DATASETS_DIR="${MRPT_DATASETS_DIR}"
    TEST_SCRATCH_DIR="${CMAKE_CURRENT_BINARY_DIR}/scratch")
  mrpt_evidential_warnings(${name})
  mrpt_evidential_budget_launcher(launcher ${MRPT_EVIDENTIAL_TEST_MEMORY_BUDGET_MB})
  # CMake 3.29 runs a test's launcher through TEST_LAUNCHER; earlier ones
  # through the emulator property, which gtest_discover_tests also honours.
  if(CMAKE_VERSION VERSION_GREATER_EQUAL 3.29)
    set_target_properties(${name} PROPERTIES TEST_LAUNCHER "${launcher}")
  else()
    set_target_properties(${name} PROPERTIES CROSSCOMPILING_EMULATOR "${launcher}")
  endif()
  add_dependencies(${name} memory_budget)
  add_dependencies(unit_suites ${name})
  # TEST_PREFIX only when given: CMake 3.31 (Debian 13) warns of an empty one.
  set(prefix)
  if(arg_TEST_PREFIX)
    set(prefix TEST_PREFIX "${arg_TEST_PREFIX}")
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 ${prefix}
    PROPERTIES LABELS unit)
endfunction()
