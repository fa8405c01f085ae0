# Web page tests (included by tests/CMakeLists.txt), label "web":
#  - web_build:   web/build.sh (npm ci from the lock file, web/dist) — a fixture for the others.
#  - web_modules: node's test runner on the page's pure modules (pointer locations, Hertz, VTU;
#                 modules3d.test.mjs: the 3D VTU, surface, pressure line and 3D Hertz).
#  - web_page:    end to end: a real fosls-serve on a free loopback port with a temporary
#                 database, Debian's Chromium (/usr/bin/chromium) driven by playwright-core;
#                 writes its screenshots to build/screenshots (to refresh the ones in docs/:
#                 FOSLS_REFRESH_SCREENSHOTS=1 ctest --test-dir build -R web_page).
#  - web_page3d:  the same start-up (tests/web/page_session.mjs) for the 3D job view: hertz_3d at
#                 refinements 1, then a 2D job whose view must come back unchanged.
find_program(FOSLS_NODE node)
if(NOT FOSLS_NODE)
  message(WARNING "node not found: the web tests will fail (apt-get install nodejs npm)")
  set(FOSLS_NODE node)
endif()
set(WEB_TEST_DIR ${CMAKE_CURRENT_LIST_DIR})

add_test(NAME web_build COMMAND ${PROJECT_SOURCE_DIR}/web/build.sh)
set_tests_properties(web_build PROPERTIES LABELS web FIXTURES_SETUP web_deps TIMEOUT 300
                     RESOURCE_LOCK web_node_modules)

add_test(NAME web_modules COMMAND ${FOSLS_NODE} --test ${WEB_TEST_DIR}/modules.test.mjs
         ${WEB_TEST_DIR}/modules3d.test.mjs
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(web_modules PROPERTIES LABELS web TIMEOUT 60)

add_test(NAME web_page COMMAND ${FOSLS_NODE} --test ${WEB_TEST_DIR}/page.test.mjs
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(web_page PROPERTIES
  LABELS web
  FIXTURES_REQUIRED web_deps
  RESOURCE_LOCK web_node_modules
  TIMEOUT 180
  ENVIRONMENT "FOSLS_SERVE=$<TARGET_FILE:fosls-serve>;FOSLS_WEB_ROOT=${PROJECT_SOURCE_DIR}/web;FOSLS_SCREENSHOTS=${CMAKE_BINARY_DIR}/screenshots")

add_test(NAME web_page3d COMMAND ${FOSLS_NODE} --test ${WEB_TEST_DIR}/page3d.test.mjs
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(web_page3d PROPERTIES
  LABELS web
  FIXTURES_REQUIRED web_deps
  RESOURCE_LOCK web_node_modules
  TIMEOUT 120
  ENVIRONMENT "FOSLS_SERVE=$<TARGET_FILE:fosls-serve>;FOSLS_WEB_ROOT=${PROJECT_SOURCE_DIR}/web;FOSLS_SCREENSHOTS=${CMAKE_BINARY_DIR}/screenshots")
