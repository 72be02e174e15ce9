# How a GoogleTest executable's tests reach ctest.
#
# By default each test is its own ctest test (gtest_discover_tests): `ctest -R Name` runs one,
# and a failure is named by ctest. With CAROM_TEST_SHARDS set to N > 0, each executable is
# instead N ctest tests, `<prefix>shard_K_of_N`, each running the K-th of N shards of its tests
# in one process (GoogleTest's GTEST_SHARD_INDEX / GTEST_TOTAL_SHARDS). The clang-asan preset
# uses it: there a test process costs more to start than most tests take to run (AddressSanitizer
# maps its shadow memory and checks for leaks at exit, in each of some 600 processes), so the
# suite spends less time starting processes, and the shards keep both cores busy
# (docs/design.md, "CI time"). A shard's output names any test that fails.
include(GoogleTest)

set(CAROM_TEST_SHARDS 0 CACHE STRING
    "Run each GoogleTest executable as this many ctest tests (shards); 0: one ctest test a test")

# carom_add_gtest(target [TEST_PREFIX prefix])
function(carom_add_gtest target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "TEST_PREFIX" "")
  if(NOT CAROM_TEST_SHARDS MATCHES "^[0-9]+$")
    message(FATAL_ERROR "CAROM_TEST_SHARDS must be a whole number, not '${CAROM_TEST_SHARDS}'")
  endif()
  if(CAROM_TEST_SHARDS EQUAL 0)
    gtest_discover_tests(${target} TEST_PREFIX "${arg_TEST_PREFIX}" DISCOVERY_TIMEOUT 60)
    return()
  endif()
  if(arg_TEST_PREFIX)
    set(prefix ${arg_TEST_PREFIX})
  else()
    set(prefix ${target}.)
  endif()
  math(EXPR last "${CAROM_TEST_SHARDS} - 1")
  foreach(shard RANGE ${last})
    set(name "${prefix}shard_${shard}_of_${CAROM_TEST_SHARDS}")
    add_test(NAME ${name} COMMAND ${target} --gtest_brief=1)
    set_tests_properties(${name} PROPERTIES
      ENVIRONMENT "GTEST_SHARD_INDEX=${shard};GTEST_TOTAL_SHARDS=${CAROM_TEST_SHARDS}")
  endforeach()
endfunction()
