# Coulomb friction in load steps (issue 49, docs/performance.md "Friction"), label `friction`:
# the shipped cattaneo_mindlin (press, then shift) at refinements 2–4, seconds each.
#   ctest --test-dir build -L friction --output-on-failure
add_executable(friction_load_steps_test ${CMAKE_CURRENT_LIST_DIR}/friction_load_steps_test.cpp)
target_link_libraries(friction_load_steps_test PRIVATE fosls_internals GTest::gtest_main)
gtest_discover_tests(friction_load_steps_test PROPERTIES LABELS friction DISCOVERY_TIMEOUT 60)
