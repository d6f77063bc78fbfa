# The test oracle (CGAL's segment Voronoi diagram read in the canonical ids of
# design/algorithm.md section 7), random polygon generators and curve comparison:
# headers in include/pma_test/, used only by tests and benchmarks.
#
# This file is also run as a CMake script (cmake -P) by the sdg_pairs tests below, to check
# an exact exit status and the output: variables PMA_CMD (the program), PMA_ARGS (its
# arguments, ';'-separated), optionally PMA_INPUT_TEXT (written to PMA_INPUT_FILE, which is
# then appended to the arguments), PMA_EXPECT_EXIT, and PMA_EXPECT_LINES (lines that must
# occur in stdout, separated by '|').
if(CMAKE_SCRIPT_MODE_FILE)
  set(args ${PMA_ARGS})
  if(DEFINED PMA_INPUT_TEXT)
    file(WRITE "${PMA_INPUT_FILE}" "${PMA_INPUT_TEXT}\n")
    list(APPEND args "${PMA_INPUT_FILE}")
  endif()
  execute_process(COMMAND "${PMA_CMD}" ${args}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT "${rc}" STREQUAL "${PMA_EXPECT_EXIT}")
    message(FATAL_ERROR "exit status '${rc}', expected ${PMA_EXPECT_EXIT}; stderr: ${err}")
  endif()
  if(DEFINED PMA_EXPECT_LINES)
    string(REPLACE "|" ";" lines "${PMA_EXPECT_LINES}")
    foreach(line IN LISTS lines)
      string(FIND "${out}" "${line}\n" pos)
      if(pos EQUAL -1)
        message(FATAL_ERROR "missing output line '${line}'; output:\n${out}")
      endif()
    endforeach()
  endif()
  string(FIND "${err}" "\n" nl)
  if(NOT "${PMA_EXPECT_EXIT}" STREQUAL "0")
    # one-line error message
    string(LENGTH "${err}" len)
    math(EXPR last "${len} - 1")
    if(len EQUAL 0 OR NOT nl EQUAL last)
      message(FATAL_ERROR "expected a one-line error message, got: '${err}'")
    endif()
  endif()
  return()
endif()

# Self-test of the oracle, the generators and the comparison helper.
pma_add_test_program(test_oracle_self)
add_test(NAME oracle_self COMMAND test_oracle_self)

# sdg_pairs [--branches] [--time] INPUT: prints "pair A B L" (and "branch ..." lines).
pma_add_test_program(sdg_pairs)

function(pma_sdg_pairs_test name expect_exit)
  cmake_parse_arguments(T "" "INPUT_TEXT;EXPECT_LINES" "ARGS" ${ARGN})
  set(defs -DPMA_CMD=$<TARGET_FILE:sdg_pairs> "-DPMA_ARGS=${T_ARGS}"
           -DPMA_EXPECT_EXIT=${expect_exit})
  if(DEFINED T_INPUT_TEXT)
    list(APPEND defs "-DPMA_INPUT_TEXT=${T_INPUT_TEXT}"
                     -DPMA_INPUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/${name}.wkt)
  endif()
  if(DEFINED T_EXPECT_LINES)
    list(APPEND defs "-DPMA_EXPECT_LINES=${T_EXPECT_LINES}")
  endif()
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} ${defs} -P ${CMAKE_CURRENT_LIST_FILE})
endfunction()

# the L-shaped hexagon of test_oracle_self (hand-derived values)
pma_sdg_pairs_test(sdg_pairs_L 0
  ARGS --branches
  INPUT_TEXT "POLYGON ((0 0, 2 0, 2 1, 1 1, 1 2, 0 2, 0 0))"
  EXPECT_LINES "pair e0.0 e0.1 0.70710678118654757|pair e0.0 e0.2 0.5|pair e0.3 e0.5 0.5|pair e0.0 v0.3 0.42577062416473832|pair e0.5 v0.3 0.42577062416473832|branch e0.0 e0.1 e0.2 1.5 0.5 0.5|branch e0.0 e0.5 v0.3 0.58578643762690497 0.58578643762690497 0.58578643762690497")
pma_sdg_pairs_test(sdg_pairs_comb50 0
  ARGS ${PMA_TEST_DATA}/syn_comb50.wkt
  EXPECT_LINES "pair e0.199 e0.200 0.70710678118654757|pair e0.198 e0.200 3.5")
# bad input: exit status 2 and a one-line message
pma_sdg_pairs_test(sdg_pairs_missing_file 2 ARGS ${PMA_TEST_DATA}/no_such_file.wkt)
pma_sdg_pairs_test(sdg_pairs_malformed 2 INPUT_TEXT "POLYGON ((0 0, 1 1, 1 0")
pma_sdg_pairs_test(sdg_pairs_self_intersecting 2
  INPUT_TEXT "POLYGON ((0 0, 1 1, 1 0, 0 1, 0 0))")
pma_sdg_pairs_test(sdg_pairs_usage 2 ARGS --no-such-option)
