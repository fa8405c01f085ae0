# Coulomb friction on the fine meshes where the fixed point of the slip bounds used to stall
# (issue 49, docs/performance.md "Friction"), label `friction_large`: 434k and 1.7M unknowns,
# minutes each and up to 1.3 GiB. They skip unless asked, so the default run stays short:
#   FOSLS_LARGE_TESTS=1 ctest --test-dir build -L friction_large --output-on-failure
add_executable(friction_large_test ${CMAKE_CURRENT_LIST_DIR}/friction_large_test.cpp)
target_link_libraries(friction_large_test PRIVATE fosls_internals GTest::gtest_main)
gtest_discover_tests(friction_large_test PROPERTIES LABELS friction_large TIMEOUT 3600
                     DISCOVERY_TIMEOUT 60)
