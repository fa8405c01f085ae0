# Service tests (included by tests/CMakeLists.txt).
#  - unit: the store, workers and HTTP layer in-process, with a fake solver step (test code).
#  - integration: the real build/bin/fosls-serve on a free loopback port, driven over HTTP.
set(SERVICE_TEST_DIR ${CMAKE_CURRENT_LIST_DIR})
foreach(name request_checks_test sqlite_job_store_test worker_pool_test http_api_test)
  add_executable(${name} ${SERVICE_TEST_DIR}/${name}.cpp)
  target_link_libraries(${name} PRIVATE fosls_service GTest::gtest_main)
  target_include_directories(${name} PRIVATE ${SERVICE_TEST_DIR})
  gtest_discover_tests(${name} PROPERTIES LABELS unit TIMEOUT 120 DISCOVERY_TIMEOUT 60)
endforeach()
