# Script mode (cmake -P): writes CTEST_FILE, one ctest test per GoogleTest suite of
# TEST_EXECUTABLE, run as `TEST_EXECUTABLE --gtest_filter=SUITE.*` and named `SUITE.*`.
# The ASan build's tests use it instead of gtest_discover_tests' one test per process: there
# every process pays the sanitizer runtime's start-up and its leak check at exit, which for the
# suite's hundreds of short tests cost more than the tests.
# Value-parameterized suites ("Prefix/Suite") keep a test per parameter: their cases are few and
# long (a format's mutations, a whole scene), and the assimp fence's fork costs far more in a
# process that many tests have grown than in a fresh one.
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
# first and the short ones fill in beside them. A few suites of few tests run for long (whole
# batches of models through the program, the viewer under Xvfb): they start first, as do the
# parameterized mutation sweeps.
set(long_suites CliFrames View CliFraming)
macro(add_suite_test)
  if(NOT filter STREQUAL "")
    set(cost ${tests})
    list(FIND long_suites "${suite_name}" long)
    if(long GREATER -1)
      set(cost 1000)
    endif()
    string(APPEND content
           "add_test([==[${filter}]==] [==[${TEST_EXECUTABLE}]==] [==[--gtest_filter=${filter}]==])\n"
           "set_tests_properties([==[${filter}]==] PROPERTIES COST ${cost})\n")
  endif()
endmacro()
set(parameterized "")
foreach(line IN LISTS lines)
  # A suite's line is its name and a dot ("Suite." or "Prefix/Suite.  # TypeParam = ...");
  # its tests' lines are indented ("  Test/param  # GetParam() = ...").
  if(line MATCHES "^([A-Za-z0-9_/]+)\\.")
    set(suite "${CMAKE_MATCH_1}")
    add_suite_test()
    set(suite_name "${suite}")
    set(filter "")
    set(tests 0)
    set(parameterized "")
    if(suite MATCHES "/")
      set(parameterized "${suite}")
    else()
      set(filter "${suite}.*")
    endif()
  elseif(line MATCHES "^  ([A-Za-z0-9_/]+)")
    if(parameterized STREQUAL "")
      math(EXPR tests "${tests} + 1")
    else()
      set(name "${parameterized}.${CMAKE_MATCH_1}")
      string(APPEND content
             "add_test([==[${name}]==] [==[${TEST_EXECUTABLE}]==] [==[--gtest_filter=${name}]==])\n"
             "set_tests_properties([==[${name}]==] PROPERTIES COST 500)\n")
    endif()
  endif()
endforeach()
add_suite_test()
if(content STREQUAL "")
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests listed no suite:\n${listing}")
endif()
file(WRITE "${CTEST_FILE}" "${content}")
