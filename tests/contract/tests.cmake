# The published contract: the JSON Schemas agree with the reader, through the real program.
set(CONTRACT_DIR ${CMAKE_CURRENT_LIST_DIR})
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  add_test(NAME contract_case_schema
           COMMAND ${Python3_EXECUTABLE} ${CONTRACT_DIR}/case_schema_test.py
                   --bin $<TARGET_FILE:fosls-contact> --source ${PROJECT_SOURCE_DIR})
  set_tests_properties(contract_case_schema PROPERTIES LABELS unit TIMEOUT 120)
  add_test(NAME contract_msh_workflow
           COMMAND ${Python3_EXECUTABLE} ${CONTRACT_DIR}/msh_workflow_test.py
                   --bin $<TARGET_FILE:fosls-contact> --source ${PROJECT_SOURCE_DIR})
  set_tests_properties(contract_msh_workflow PROPERTIES LABELS unit TIMEOUT 300)
  add_test(NAME contract_service
           COMMAND ${Python3_EXECUTABLE} ${CONTRACT_DIR}/service_contract_test.py
                   --serve $<TARGET_FILE:fosls-serve> --source ${PROJECT_SOURCE_DIR})
  set_tests_properties(contract_service PROPERTIES LABELS integration TIMEOUT 300)
endif()
