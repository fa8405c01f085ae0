# Service tests (included by tests/CMakeLists.txt).
#  - unit: the store, workers and HTTP layer in-process, with a fake solver step (test code).
#  - integration: the real build/bin/fosls-serve on a free loopback port, driven over HTTP.
set(SERVICE_TEST_DIR ${CMAKE_CURRENT_LIST_DIR})
foreach(name request_checks_test sqlite_job_store_test worker_pool_test http_api_test stored_body_test
             job_process_test store_url_test postgres_job_store_test request_head_test
             bounded_http_server_test)
  add_executable(${name} ${SERVICE_TEST_DIR}/${name}.cpp)
  target_link_libraries(${name} PRIVATE fosls_service GTest::gtest_main)
  target_include_directories(${name} PRIVATE ${SERVICE_TEST_DIR})
  gtest_discover_tests(${name} PROPERTIES LABELS unit TIMEOUT 120 DISCOVERY_TIMEOUT 60)
endforeach()
add_dependencies(job_process_test fosls-solve-job)  # runs the real solve process

# One contract, two stores: the same tests on SQLite and on a throwaway PostgreSQL server that
# the test process starts itself (postgres_cluster.hpp). One ctest entry per store, so that the
# PostgreSQL tests share one server instead of running initdb per test.
add_executable(job_store_contract_test ${SERVICE_TEST_DIR}/job_store_contract_test.cpp
                                       ${SERVICE_TEST_DIR}/job_store_recovery_test.cpp)
target_link_libraries(job_store_contract_test PRIVATE fosls_service GTest::gtest_main)
target_include_directories(job_store_contract_test PRIVATE ${SERVICE_TEST_DIR})
foreach(store sqlite postgresql)
  add_test(NAME JobStoreContract.${store}
           COMMAND job_store_contract_test --gtest_filter=Stores/JobStoreContract.*/${store})
  set_tests_properties(JobStoreContract.${store} PROPERTIES LABELS unit TIMEOUT 300)
endforeach()

# Integration: needs the real solver behind fosls-serve.
foreach(name service_integration_test service_isolation_test service_convergence_test
             service_3d_test hostile_http_test hostile_probes_test)
  add_executable(${name} ${SERVICE_TEST_DIR}/${name}.cpp)
  target_link_libraries(${name} PRIVATE GTest::gtest_main PkgConfig::HTTPLIB PkgConfig::SQLITE3
                                        nlohmann_json::nlohmann_json)
  target_include_directories(${name} PRIVATE ${SERVICE_TEST_DIR})
  target_compile_definitions(${name} PRIVATE
    FOSLS_SERVE_PATH="$<TARGET_FILE:fosls-serve>"
    FOSLS_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/solver/examples")
  add_dependencies(${name} fosls-serve)
  gtest_discover_tests(${name} PROPERTIES LABELS integration TIMEOUT 240 DISCOVERY_TIMEOUT 60)
endforeach()

# Several processes on one PostgreSQL database (a throwaway server the test starts): one
# API-only fosls-serve and three fosls-worker, with workers and the API killed during the run.
add_executable(cluster_integration_test ${SERVICE_TEST_DIR}/cluster_integration_test.cpp)
target_link_libraries(cluster_integration_test PRIVATE fosls_service GTest::gtest_main)
target_include_directories(cluster_integration_test PRIVATE ${SERVICE_TEST_DIR})
target_compile_definitions(cluster_integration_test PRIVATE
  FOSLS_SERVE_PATH="$<TARGET_FILE:fosls-serve>"
  FOSLS_WORKER_PATH="$<TARGET_FILE:fosls-worker>"
  FOSLS_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/solver/examples")
add_dependencies(cluster_integration_test fosls-serve fosls-worker)
gtest_discover_tests(cluster_integration_test PROPERTIES LABELS integration TIMEOUT 400
                     DISCOVERY_TIMEOUT 60)

# The docs name only routes the server has (README.md and docs/*.md against api_routes()).
add_executable(doc_routes_test ${SERVICE_TEST_DIR}/doc_routes_test.cpp)
target_link_libraries(doc_routes_test PRIVATE fosls_service GTest::gtest_main)
target_include_directories(doc_routes_test PRIVATE ${PROJECT_SOURCE_DIR}/service)
gtest_discover_tests(doc_routes_test PROPERTIES LABELS unit TIMEOUT 60 DISCOVERY_TIMEOUT 60)
