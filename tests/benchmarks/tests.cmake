# Benchmarks are programs, not tests: they print tables (see README "Performance").
add_executable(fosls-bench-assembly ${CMAKE_CURRENT_LIST_DIR}/assembly_bench.cpp)
target_link_libraries(fosls-bench-assembly PRIVATE fosls_internals)
