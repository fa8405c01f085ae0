# The Python client of the job API (clients/python/fosls_client.py) against a real fosls-serve
# that its test starts (clients/python/test_fosls_client.py).
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  add_test(NAME python_client
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/clients/python/test_fosls_client.py -v)
  set_tests_properties(python_client PROPERTIES LABELS integration TIMEOUT 300
    ENVIRONMENT "FOSLS_SERVE=$<TARGET_FILE:fosls-serve>;FOSLS_SOURCE=${PROJECT_SOURCE_DIR}")
endif()
