# Installs the carom build in CAROM_BUILD_DIR into WORK_DIR/prefix, then configures, builds and
# runs the consumer project against it, which links every library carom installs. With WITH_TOOL
# the installed tool is checked too: the examples (EXAMPLES_DIR) installed beside it, and its help
# naming where they are, also once the installed tree has been moved. Fails on any step's
# non-zero exit or any difference.
function(run_step)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "step failed (${result}): ${ARGV}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run_step(${CMAKE_COMMAND} --install ${CAROM_BUILD_DIR} --prefix ${prefix})
run_step(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build -G ${GENERATOR}
  -DCMAKE_PREFIX_PATH=${prefix}
  -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
  "-DCMAKE_EXE_LINKER_FLAGS=${EXE_LINKER_FLAGS}")
run_step(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run_step(${WORK_DIR}/build/consumer)
run_step(${WORK_DIR}/build/scene_consumer)
run_step(${WORK_DIR}/build/science_consumer)

if(NOT WITH_TOOL)
  return()
endif()

# The installed tool's help names the installed examples, found from where the tool is.
function(check_installed_tool prefix)
  set(examples ${prefix}/share/carom/examples)
  file(GLOB wanted RELATIVE ${EXAMPLES_DIR} ${EXAMPLES_DIR}/*)
  file(GLOB installed RELATIVE ${examples} ${examples}/*)
  if(NOT wanted OR NOT installed STREQUAL wanted)
    message(FATAL_ERROR "installed examples in ${examples}: '${installed}', wanted '${wanted}'")
  endif()
  execute_process(COMMAND ${prefix}/bin/carom --help OUTPUT_VARIABLE help RESULT_VARIABLE result)
  string(FIND "${help}" "Example scenes (examples/ in the verbs' help): ${examples}\n" at)
  if(NOT result EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "carom --help (exit ${result}) does not name ${examples}:\n${help}")
  endif()
  run_step(${prefix}/bin/carom info ${examples}/billiards-frictionless.json)
  if(NOT EXISTS ${prefix}/share/carom/scene.schema.json)
    message(FATAL_ERROR "the scene format's schema is not installed in ${prefix}/share/carom")
  endif()
endfunction()

check_installed_tool(${prefix})
file(RENAME ${prefix} ${WORK_DIR}/moved)
check_installed_tool(${WORK_DIR}/moved)
