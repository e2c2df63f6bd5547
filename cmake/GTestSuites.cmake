# Script mode (cmake -P): writes CTEST_FILE, one ctest test per GoogleTest suite of
# TEST_EXECUTABLE, run as `TEST_EXECUTABLE --gtest_filter=SUITE.*` and named `SUITE.*`.
# The ASan build's tests use it instead of gtest_discover_tests' one test per process: there
# every process pays the sanitizer runtime's start-up and its leak check at exit, which for the
# suite's hundreds of short tests cost more than the tests.
execute_process(COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing ERROR_VARIABLE errors RESULT_VARIABLE result TIMEOUT 120)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests failed (${result}):\n${errors}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(content "")
set(filter "")
set(tests 0)
# Each suite's test is given a COST of its number of tests, so that ctest starts the big suites
# first and the short ones fill in beside them.
macro(add_suite_test)
  if(NOT filter STREQUAL "")
    string(APPEND content
           "add_test([==[${filter}]==] [==[${TEST_EXECUTABLE}]==] [==[--gtest_filter=${filter}]==])\n"
           "set_tests_properties([==[${filter}]==] PROPERTIES COST ${tests})\n")
  endif()
endmacro()
foreach(line IN LISTS lines)
  # A suite's line is its name and a dot ("Suite." or "Prefix/Suite.  # TypeParam = ...");
  # its tests' lines are indented.
  if(line MATCHES "^([A-Za-z0-9_/]+)\\.")
    add_suite_test()
    set(filter "${CMAKE_MATCH_1}.*")
    set(tests 0)
  elseif(line MATCHES "^  [A-Za-z0-9_/]")
    math(EXPR tests "${tests} + 1")
  endif()
endforeach()
add_suite_test()
if(content STREQUAL "")
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests listed no suite:\n${listing}")
endif()
file(WRITE "${CTEST_FILE}" "${content}")
