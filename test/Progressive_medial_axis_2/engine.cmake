# The medial axis against the Segment_Delaunay_graph_2 oracle.
pma_add_test_program(test_medial_axis_oracle)
# Boundary evolution: the curve evolution runs in slabs first from 400
# vertices on here (32,768 per slab in the library), so that the data shapes
# test that path and the small random polygons the sequential one.
target_compile_definitions(test_medial_axis_oracle PRIVATE CGAL_PMA2_EVOLUTION_SLAB_VERTICES=200)
add_test(NAME oracle_filtered COMMAND test_medial_axis_oracle --only regressions,random,holes,data,lakes,touching,union,double)
# Degenerate input (integer grids, Hilbert, Koch, regular polygons, glyphs):
# every exact tie decided, against the oracle; and finely flattened glyphs,
# whose default one-shot takes boundary evolution.
add_test(NAME oracle_degenerate COMMAND test_medial_axis_oracle --only degenerate,fine)
# The fallbacks of the exact stages from 128-bit to GMP rationals inside real
# merges (the one-root and nested-root numbers redone in Gmpq where a result
# overflows): no test shape overflows 128 bits, so in this build the 128-bit
# rationals overflow at 40 bits.  This build also confirms each tie decided
# by symmetry (mirror_tie()) in nested-root numbers, and fails if one is not;
# and each coordinate of a disk rounded from its axis-parallel sites
# (axis_aligned_disk(): the map-like polygons of the section lakes).
pma_add_test_program(test_medial_axis_oracle_gmp_fallback SOURCE test_medial_axis_oracle.cpp)
target_compile_definitions(test_medial_axis_oracle_gmp_fallback PRIVATE CGAL_PMA2_SMALL_RATIONAL_TEST_BITS=40
                           CGAL_PMA2_CHECK_MIRROR_TIES CGAL_PMA2_CHECK_AXIS_ALIGNED_DISKS)
add_test(NAME oracle_degenerate_gmp_fallback COMMAND test_medial_axis_oracle_gmp_fallback --only degenerate,lakes)
# The double-precision model: its promise (the exact topology, merges with
# uncertain decisions redone exactly) on the data and degenerate shapes too.
add_test(NAME oracle_epick COMMAND test_medial_axis_oracle --traits epick --quick)
add_test(NAME oracle_exact COMMAND test_medial_axis_oracle --traits exact --quick --only random,union)
# Boundary evolution (--driver boundary): the axis of every step compared
# (random polygons, with holes), or of steps spread over the run (shapes).
add_test(NAME oracle_boundary COMMAND test_medial_axis_oracle --driver boundary --only random,holes)
add_test(NAME oracle_boundary_shapes COMMAND test_medial_axis_oracle --driver boundary --quick
         --only regressions,data,degenerate,touching)
add_test(NAME oracle_boundary_epick COMMAND test_medial_axis_oracle --driver boundary --traits epick --quick
         --only random,holes,touching)
set_tests_properties(oracle_filtered oracle_degenerate oracle_degenerate_gmp_fallback oracle_epick oracle_exact oracle_boundary oracle_boundary_shapes
                     oracle_boundary_epick PROPERTIES TIMEOUT 1800)

# The command-line tool's contract, against the oracle program sdg_pairs
# (defined in oracle.cmake).
if(TARGET sdg_pairs)
  pma_add_test_program(test_tool)
  add_test(NAME tool COMMAND test_tool $<TARGET_FILE:progressive_medial_axis> $<TARGET_FILE:sdg_pairs> ${PMA_TEST_DATA})
  set_tests_properties(tool PROPERTIES TIMEOUT 600)
endif()

# The progressive viewer (--html) in Debian's chromium, headless: screenshots
# at two slider positions differ and are not blank.  Skipped (exit 77) when
# chromium or python3-pil is absent.  Debian's python3 (python3-pil).
find_program(PMA_SYSTEM_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(PMA_SYSTEM_PYTHON3 AND TARGET progressive_medial_axis)
  add_test(NAME html_viewer
           COMMAND ${PMA_SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/html_viewer_test.py
                   $<TARGET_FILE:progressive_medial_axis> ${PMA_TEST_DATA}/syn_spiral20.wkt
                   ${CMAKE_CURRENT_BINARY_DIR}/html_viewer)
  set_tests_properties(html_viewer PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
endif()

# compare_pairs SHAPE OURS ORACLE: used by scripts/check_oracle.sh.
pma_add_test_program(compare_pairs)

# The exact one-root numbers that decide ties in the filtered traits.
pma_add_test_program(test_number_types)
add_test(NAME number_types COMMAND test_number_types)

# The public C++ interface, as a user meets it (every overload and accessor,
# the kernels, navigation, the fixed bugs), with the tool for --shape-out.
pma_add_test_program(test_api)
add_test(NAME api COMMAND test_api $<TARGET_FILE:progressive_medial_axis> ${PMA_TEST_DATA})

# What users do with an axis: significance (extended grassfire), pruning,
# centerlines and width profiles, the maximum inscribed circle, Bezier arcs.
pma_add_test_program(test_pruning)
add_test(NAME pruning COMMAND test_pruning)

# ThreadSanitizer: 4 threads read one result while 4 threads build 4 results
# (test_api --threads), in a build of its own with -fsanitize=thread.
option(PMA_SANITIZER_TESTS "Build and run the tests under sanitizers" ON)
if(PMA_SANITIZER_TESTS AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  pma_add_test_program(test_api_tsan SOURCE test_api.cpp)
  # the one-shot runs sequentially here: ThreadSanitizer cannot see the
  # synchronisation inside the (uninstrumented) libtbb
  target_compile_definitions(test_api_tsan PRIVATE CGAL_PMA2_NO_TBB)
  target_compile_options(test_api_tsan PRIVATE -fsanitize=thread -O1 -g)
  target_link_options(test_api_tsan PRIVATE -fsanitize=thread)
  add_test(NAME api_threads_tsan COMMAND test_api_tsan --threads)
  set_tests_properties(api_threads_tsan PROPERTIES ENVIRONMENT "TSAN_OPTIONS=halt_on_error=1 exitcode=66")

  # AddressSanitizer and UndefinedBehaviorSanitizer: the readers and the
  # check of the input (test_input), the tool's contract (test_tool running a
  # sanitized tool), the engine's drivers and the analysis (test_pruning).
  set(pma_asan_flags -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -O1 -g)
  foreach(name test_input test_pruning)
    pma_add_test_program(${name}_asan SOURCE ${name}.cpp)
  endforeach()
  pma_tool_executable(progressive_medial_axis_asan)
  foreach(target test_input_asan test_pruning_asan progressive_medial_axis_asan)
    target_compile_options(${target} PRIVATE ${pma_asan_flags})
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endforeach()
  add_test(NAME input_asan COMMAND test_input_asan)
  add_test(NAME pruning_asan COMMAND test_pruning_asan)
  if(TARGET sdg_pairs)
    add_test(NAME tool_asan COMMAND test_tool $<TARGET_FILE:progressive_medial_axis_asan> $<TARGET_FILE:sdg_pairs> ${PMA_TEST_DATA}
             --sanitized)
  endif()
  set_tests_properties(input_asan pruning_asan PROPERTIES TIMEOUT 1200
                       ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1:abort_on_error=1;UBSAN_OPTIONS=print_stacktrace=1")
endif()
