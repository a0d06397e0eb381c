# Installs the build tree PROJECT_BINARY_DIR into a scratch prefix (or, with
# PREFIX, takes what is installed there: /usr of the Debian packages), then
# runs every installed program from there and configures, builds and runs the
# consumer project against it: its own program, the README's example and a
# program of the algebra alone. Fails on the first step that fails.
file(REMOVE_RECURSE ${WORK_DIR})
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}")
  endif()
endfunction()
if(PREFIX)
  set(prefix ${PREFIX})
else()
  set(prefix ${WORK_DIR}/prefix)
  step(${CMAKE_COMMAND} --install ${PROJECT_BINARY_DIR} --prefix ${prefix})
endif()

# Every installed program runs from the prefix as it is, without the build
# tree or LD_LIBRARY_PATH.
string(REPLACE "," ";" programs "${INSTALLED_PROGRAMS}")
foreach(program IN LISTS programs)
  step(${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH
    ${prefix}/bin/${program} --help)
endforeach()

# The README's C++ example, exactly as written there.
file(READ ${README} readme)
string(REGEX MATCH "```cpp\n([^`]*)```" block "${readme}")
if(NOT block)
  message(FATAL_ERROR "no C++ example found in ${README}")
endif()
file(WRITE ${WORK_DIR}/readme_example.cpp "${CMAKE_MATCH_1}")

step(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
  -DREADME_EXAMPLE=${WORK_DIR}/readme_example.cpp)
# The package found is the one under test, not another installed copy (the
# Debian packages in /usr, while their test runs).
file(STRINGS ${WORK_DIR}/build/CMakeCache.txt found REGEX "^mrpt_evidential_DIR:")
string(REGEX REPLACE "^[^=]*=" "" found "${found}")
string(FIND "${found}" "${prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "the consumer found mrpt_evidential in ${found}, not under ${prefix}")
endif()
step(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
step(${WORK_DIR}/build/consumer)
step(${WORK_DIR}/build/readme_example)
step(${WORK_DIR}/build/algebra_only)
