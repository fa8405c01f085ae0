# Validation against analytic and discrete references (docs/validation.md), label
# `validation`. The full regeneration of the tables and figures is
# tests/validation/run_validation.py (needs python3-numpy and python3-matplotlib); the tests
# below re-check the coarse levels of those tables with the standard library only.
set(VALIDATION_DIR ${CMAKE_CURRENT_LIST_DIR})

# Element-wise functional against the true error of a manufactured solution.
add_executable(validation_manufactured_errors ${VALIDATION_DIR}/manufactured_errors.cpp)
target_link_libraries(validation_manufactured_errors PRIVATE fosls_internals nlohmann_json::nlohmann_json)
target_include_directories(validation_manufactured_errors PRIVATE ${PROJECT_SOURCE_DIR}/tests)

# True error and estimator on the L-shaped domain's corner singularity, uniform and adaptive.
add_executable(validation_corner_errors ${VALIDATION_DIR}/corner_errors.cpp)
target_link_libraries(validation_corner_errors PRIVATE fosls_internals nlohmann_json::nlohmann_json)
target_include_directories(validation_corner_errors PRIVATE ${PROJECT_SOURCE_DIR}/tests)

find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  foreach(check ShippedBenchmarks HertzCompressible HertzIncompressible FiniteBody
                SolverIterations ErrorEstimator SignoriniSquare CornerSingularity CornerTrueError
                DisplacementFem AxisymmetricReference)
    add_test(NAME validation_${check}
             COMMAND ${Python3_EXECUTABLE} ${VALIDATION_DIR}/test_validation.py
                     --bin $<TARGET_FILE:fosls-contact>
                     --estimator $<TARGET_FILE:validation_manufactured_errors>
                     --corner $<TARGET_FILE:validation_corner_errors> ${check})
    set_tests_properties(validation_${check} PROPERTIES LABELS validation TIMEOUT 300)
  endforeach()
endif()

# The force-indentation figure's script (docs/validation.md §9) on refinement 2: its sweep
# converges at every point and the stiffness F/δ grows as 2D Hertz's, within 0.015 relative to
# the first point (measured 0.0095; 0.0036 on refinement 3, the figure's). Debian's python3,
# which has matplotlib (docker/install-deps.sh), through the script's #! line.
add_test(NAME validation_ForceIndentation
         COMMAND ${VALIDATION_DIR}/force_indentation.py --bin $<TARGET_FILE:fosls-contact>
                 --refinements 2 --figure ${CMAKE_BINARY_DIR}/hertz_force_indentation.svg
                 --check 0.015)
set_tests_properties(validation_ForceIndentation PROPERTIES LABELS validation TIMEOUT 300)
