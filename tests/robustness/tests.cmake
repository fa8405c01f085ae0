# The multilevel solver on cases set up as users set them up (issue 10, docs/validation.md
# "Robustness"), label `robustness`: one test per case, each solved by mmg, tnnmg and pdas.
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  file(GLOB ROBUSTNESS_CASES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/cases/*.json)
  foreach(case ${ROBUSTNESS_CASES})
    get_filename_component(name ${case} NAME_WE)
    add_test(NAME robustness_${name}
             COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/robustness.py
                     --bin $<TARGET_FILE:fosls-contact> ${case})
    set_tests_properties(robustness_${name} PROPERTIES LABELS robustness TIMEOUT 300)
  endforeach()
endif()
