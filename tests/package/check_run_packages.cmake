# make run installs the Makefile's RUN_PACKAGES and builds carom_cli with the release preset. This
# checks, on a machine that has everything, that nothing more is needed: the release and cli
# presets are configured in WORK_DIR with GoogleTest, Google Benchmark, Box2D and Python hidden
# (CMAKE_DISABLE_FIND_PACKAGE_*: a REQUIRED search for one of them is an error), every REQUIRED
# package search that configuring reaches in SOURCE_DIR must map to a package of RUN_PACKAGES,
# and RUN_PACKAGES must hold nothing else. The cli preset must not look for the test, benchmark
# or peer packages at all. Run with cmake -P; MAKE_PROGRAM reads RUN_PACKAGES from the Makefile.

cmake_minimum_required(VERSION 3.25)

# The Debian package behind each package that configuring the tool searches for.
set(debian_nlohmann_json nlohmann-json3-dev)
set(debian_CLI11 libcli11-dev)
set(debian_fmt libfmt-dev)
set(debian_Threads g++)  # the C library's headers come with the compiler
set(debian_PkgConfig pkg-config)
set(debian_cairo libcairo2-dev)  # pkg_check_modules
# Needed without a search: CMake and Ninja (the presets' generator), the presets' compiler, and
# the ffmpeg program that make run's animation is encoded with.
set(needed cmake ninja-build g++ ffmpeg)

execute_process(
  COMMAND ${MAKE_PROGRAM} -s --no-print-directory -C ${SOURCE_DIR}
    "--eval=carom-print-run-packages: ; @echo $(RUN_PACKAGES)" carom-print-run-packages
  OUTPUT_VARIABLE run_packages OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE result)
if(NOT result EQUAL 0 OR run_packages STREQUAL "")
  message(FATAL_ERROR "cannot read RUN_PACKAGES from ${SOURCE_DIR}/Makefile (exit ${result})")
endif()
separate_arguments(run_packages UNIX_COMMAND "${run_packages}")

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
string(REGEX REPLACE "([][+.*()^$?|\\])" "\\\\\\1" source_pattern "${SOURCE_DIR}")
foreach(preset IN ITEMS release cli)
  set(trace ${WORK_DIR}/${preset}.trace)
  execute_process(
    COMMAND ${CMAKE_COMMAND} --preset ${preset} -B ${WORK_DIR}/${preset}
      -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON
      -DCMAKE_DISABLE_FIND_PACKAGE_box2d=ON -DCMAKE_DISABLE_FIND_PACKAGE_Python3=ON
      --trace-expand --trace-redirect=${trace}
    WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE result OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the ${preset} preset does not configure without the test packages:\n${log}")
  endif()
  # The tool's build graph is complete: a dry run of building it (Ninja's -n).
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/${preset} --target carom_cli -- -n
                  RESULT_VARIABLE result OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the ${preset} preset cannot build carom_cli:\n${log}")
  endif()

  # Every package search in carom's own files, as "<search>(<name> <arguments>)".
  file(STRINGS ${trace} searches
       REGEX "^${source_pattern}/.*\\([0-9]+\\): +(find_package|pkg_check_modules|find_path|find_library)\\(")
  foreach(line IN LISTS searches)
    string(REGEX REPLACE "^.*\\([0-9]+\\): +" "" call "${line}")
    if(preset STREQUAL "cli" AND call MATCHES "GTest|benchmark|box2d|chipmunk|Python3")
      message(FATAL_ERROR "the cli preset searches for a test, benchmark or peer package: ${line}")
    endif()
    if(NOT call MATCHES " REQUIRED")
      continue()
    endif()
    if(call MATCHES "^find_package\\(([A-Za-z0-9_]+)")
      set(name ${CMAKE_MATCH_1})
    elseif(call MATCHES "^pkg_check_modules\\([A-Za-z0-9_]+ .* ([a-z0-9_+-]+) *\\)$")
      set(name ${CMAKE_MATCH_1})
    else()
      message(FATAL_ERROR "a REQUIRED search this check cannot read: ${line}")
    endif()
    if(NOT DEFINED debian_${name})
      message(FATAL_ERROR "the ${preset} preset requires ${name} (${line}): add its Debian "
                          "package to RUN_PACKAGES in the Makefile and to this file's map")
    endif()
    list(APPEND needed ${debian_${name}})
  endforeach()
endforeach()

list(REMOVE_DUPLICATES needed)
foreach(package IN LISTS needed)
  if(NOT package IN_LIST run_packages)
    message(FATAL_ERROR "make run needs ${package}, which RUN_PACKAGES lacks: ${run_packages}")
  endif()
endforeach()
foreach(package IN LISTS run_packages)
  if(NOT package IN_LIST needed)
    message(FATAL_ERROR "RUN_PACKAGES holds ${package}, which building and running the tool "
                        "does not need (needed: ${needed})")
  endif()
endforeach()
list(LENGTH run_packages count)
message(STATUS "make run needs ${count} packages, all in RUN_PACKAGES: ${run_packages}")
