# The input layer: WKT / GeoJSON readers, the WKT writer and the polygon validation.
# The invalid inputs of data/invalid/ are also used by the command-line tool's test.
pma_add_test_program(test_input)
add_test(NAME input COMMAND test_input)
set_tests_properties(input PROPERTIES TIMEOUT 300)
