# Build flags shared by every carom target (library, tools, tests, benchmarks).

option(CAROM_WARNINGS_AS_ERRORS "Treat compiler warnings as errors (on in CI)" OFF)
option(CAROM_NATIVE "Compile for the host's full instruction set (-march=native); the default
  build stays portable" OFF)

function(carom_apply_build_flags target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wsign-conversion -Wnon-virtual-dtor -Wold-style-cast)
  if(CAROM_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  # Determinism: forbid fusing a*b+c into one FMA instruction. Whether the compiler fuses
  # depends on the target and the optimiser, so results would differ between builds; with
  # contraction off every + - * / sqrt is one correctly rounded IEEE operation, and a scalar loop,
  # its vectorised twin and a -march=native build give bit-identical answers.
  target_compile_options(${target} PRIVATE -ffp-contract=off)
  # carom never reads errno; without this the compiler must keep a scalar call to sqrt for the
  # errno side effect and cannot vectorise the batch kernels. Results are unchanged.
  target_compile_options(${target} PRIVATE -fno-math-errno)
  if(CAROM_NATIVE)
    target_compile_options(${target} PRIVATE -march=native)
  endif()
endfunction()

# Extra compile options for the command-line tool and its tests alone, after every other flag.
# The sanitizer preset (clang-asan) sets -O0 there: the tool's files and its tests are most of
# what that build compiles (CLI11, nlohmann-json, GoogleTest), and at -O0 clang compiles them in
# half the time, while the libraries that do the tests' work stay at -O1 (docs/design.md, "CI
# time").
set(CAROM_TOOL_OPTIONS "" CACHE STRING "Extra compile options for the carom tool and its tests")

function(carom_apply_tool_flags target)
  carom_apply_build_flags(${target})
  target_compile_options(${target} PRIVATE ${CAROM_TOOL_OPTIONS})
endfunction()

# Compiles a library as one unity file when CAROM_UNITY_CORE is on (the test presets); see the
# option in the top-level CMakeLists.txt.
function(carom_unity_library target)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${CAROM_UNITY_CORE}
                                             UNITY_BUILD_BATCH_SIZE 0)
endfunction()
