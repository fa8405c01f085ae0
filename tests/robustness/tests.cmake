# The multilevel solver on cases set up as users set them up (docs/validation.md §8), label
# `robustness`: one test per case, each solved by mmg, tnnmg and pdas; label
# `friction_robustness`: each 2D case again with Coulomb friction 𝔣 = 0.3.
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  file(GLOB ROBUSTNESS_CASES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/cases/*.json)
  foreach(case ${ROBUSTNESS_CASES})
    get_filename_component(name ${case} NAME_WE)
    add_test(NAME robustness_${name}
             COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/robustness.py
                     --bin $<TARGET_FILE:fosls-contact> ${case})
    set_tests_properties(robustness_${name} PROPERTIES LABELS robustness TIMEOUT 300)
    # The same case with Coulomb friction 𝔣 = 0.3 on every contact group, mmg and pdas (issue 49,
    # label friction_robustness). Friction is 2D only: the 3D cases are left out.
    if(NOT name MATCHES "_3d")
      add_test(NAME robustness_friction_${name}
               COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/robustness.py
                       --bin $<TARGET_FILE:fosls-contact> --friction 0.3 ${case})
      set_tests_properties(robustness_friction_${name} PROPERTIES LABELS friction_robustness
                                                                     TIMEOUT 300)
    endif()
  endforeach()
endif()
