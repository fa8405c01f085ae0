# examples/library_example.cpp prints the force and iterations fosls-contact solve writes for
# the same case, bit for bit (a case built in, and one meshed by gmsh in fosls-mesher).
add_test(NAME library_example
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/library_example_test.py
                 $<TARGET_FILE:library_example> $<TARGET_FILE:fosls-contact>
                 ${PROJECT_SOURCE_DIR}/solver/examples/signorini_square.json
                 ${PROJECT_SOURCE_DIR}/solver/examples/hertz.json)
set_tests_properties(library_example PROPERTIES LABELS integration TIMEOUT 300)
