# Benchmarks are programs, not tests: they print tables (see docs/performance.md).
add_executable(fosls-bench-assembly ${CMAKE_CURRENT_LIST_DIR}/assembly_bench.cpp)
target_link_libraries(fosls-bench-assembly PRIVATE fosls_internals)

# The displacement FEM that FOSLS is measured against (docs/validation.md §12): its own sparse LU.
find_library(UMFPACK_LIBRARY NAMES umfpack REQUIRED)
add_executable(fosls-bench-displacement ${CMAKE_CURRENT_LIST_DIR}/displacement_fem.cpp
                                        ${CMAKE_CURRENT_LIST_DIR}/displacement_elements.cpp)
target_link_libraries(fosls-bench-displacement PRIVATE fosls_internals ${UMFPACK_LIBRARY})

# The order-2 space's force, solved by pdas (docs/performance.md, "Order 2").
add_executable(fosls-bench-order2 ${CMAKE_CURRENT_LIST_DIR}/order2_force.cpp)
target_link_libraries(fosls-bench-order2 PRIVATE fosls_internals)

# Three dimensions, stage 1: the multilevel method per level (docs/performance.md, "3D").
add_executable(fosls-bench-3d ${CMAKE_CURRENT_LIST_DIR}/tet_linear.cpp)
target_link_libraries(fosls-bench-3d PRIVATE fosls_internals)

# Coulomb friction: the fixed point of the slip bounds measured (docs/performance.md, "Friction").
add_executable(coulomb-lab ${CMAKE_CURRENT_LIST_DIR}/coulomb_lab.cpp)
target_link_libraries(coulomb-lab PRIVATE fosls_internals)
