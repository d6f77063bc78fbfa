# Fuzzing (libFuzzer, with Debian's clang): the tool's WKT and GeoJSON readers
# and the engine, each for a short run under AddressSanitizer and UBSan.
# The seeds in fuzz/seeds_* include every input a fuzzer ever crashed on (a
# regression test: libFuzzer runs every seed first).  The harnesses are
# built by clang++ directly (the rest of the build may use g++).  The tests
# use a fixed random seed (-seed=1), so that a CI run does not turn red on a
# new find by chance; longer runs with other seeds are for developers:
#   build/test/Progressive_medial_axis_2/fuzz_engine -seed=N -max_total_time=600 DIR fuzz/seeds_engine
find_program(PMA_CLANGXX NAMES clang++ clang++-14)
option(PMA_FUZZ_TESTS "Build the fuzzers with clang and run them briefly as tests" ON)
set(PMA_FUZZ_SECONDS 60 CACHE STRING "How long each fuzzer runs as a test")
if(PMA_FUZZ_TESTS AND PMA_CLANGXX)
  # the tool's fast GeoJSON reader, where simdjson is found (fuzz_readers
  # compares it with the nlohmann-json one)
  set(pma_fuzz_simdjson_flags)
  set(pma_fuzz_simdjson_libs)
  if(TARGET simdjson::simdjson)
    set(pma_fuzz_simdjson_flags -DPMA_TOOL_WITH_SIMDJSON)
    set(pma_fuzz_simdjson_libs -lsimdjson)
  endif()
  foreach(fuzzer fuzz_readers fuzz_engine)
    set(src ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/${fuzzer}.cpp)
    # the headers the fuzzer includes, from clang's own dependency file
    # (IMPLICIT_DEPENDS does not see the -I directories of the command, so
    # a change of the library did not rebuild the fuzzers)
    if(CMAKE_VERSION VERSION_GREATER_EQUAL 3.20)
      set(pma_fuzz_depends -MD -MF ${CMAKE_CURRENT_BINARY_DIR}/${fuzzer}.d)
      set(pma_fuzz_depfile DEPFILE ${CMAKE_CURRENT_BINARY_DIR}/${fuzzer}.d)
    else()
      set(pma_fuzz_depends)
      set(pma_fuzz_depfile IMPLICIT_DEPENDS CXX ${src})
    endif()
    add_custom_command(
      OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/${fuzzer}
      COMMAND ${PMA_CLANGXX} -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined
              -DCGAL_PMA2_NO_TBB ${pma_fuzz_simdjson_flags} -I${PROJECT_SOURCE_DIR}/include
              -I${PROJECT_SOURCE_DIR}/tool/Progressive_medial_axis_2/include -I${CMAKE_CURRENT_SOURCE_DIR}/include
              ${pma_fuzz_depends} ${src} -o ${CMAKE_CURRENT_BINARY_DIR}/${fuzzer} -lgmp -lmpfr ${pma_fuzz_simdjson_libs}
      DEPENDS ${src}
      ${pma_fuzz_depfile}
      COMMENT "Building the fuzzer ${fuzzer} with clang")
    add_custom_target(${fuzzer}_build ALL DEPENDS ${CMAKE_CURRENT_BINARY_DIR}/${fuzzer})
  endforeach()
  foreach(what readers engine)
    set(corpus ${CMAKE_CURRENT_BINARY_DIR}/fuzz_corpus_${what})
    file(MAKE_DIRECTORY ${corpus})
    add_test(NAME fuzz_${what}
             COMMAND ${CMAKE_CURRENT_BINARY_DIR}/fuzz_${what} -max_total_time=${PMA_FUZZ_SECONDS} -timeout=30 -seed=1
                     -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix=${CMAKE_CURRENT_BINARY_DIR}/fuzz_${what}_
                     ${corpus} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/seeds_${what})
    set_tests_properties(fuzz_${what} PROPERTIES TIMEOUT 900)
  endforeach()
elseif(PMA_FUZZ_TESTS)
  message(STATUS "clang++ not found: the fuzzers are not built (install clang)")
endif()
