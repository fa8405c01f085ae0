# The container image (docker/), label `container`: builds the images with
# docker/build-image.sh (cached layers; the first build compiles the project, ~20 minutes) and
# runs docker/test-image.sh (one container, then the compose cluster with a worker stopped
# mid-job). Not part of the default run: it skips (exit 77) unless FOSLS_CONTAINER_TESTS=1,
#   FOSLS_CONTAINER_TESTS=1 ctest --test-dir build -L container --output-on-failure
add_test(NAME container_image COMMAND ${CMAKE_CURRENT_LIST_DIR}/container_test.sh
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(container_image PROPERTIES LABELS container SKIP_RETURN_CODE 77
                                                TIMEOUT 5400 RUN_SERIAL TRUE)
# Which worker the cluster test stops (docker/test-image-stop.sh), against a fake engine: the one
# holding a running job's lease in the store. Needs no engine, so it runs with the unit tests.
add_test(NAME worker_stop_choice COMMAND ${CMAKE_CURRENT_LIST_DIR}/worker_stop_test.sh
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(worker_stop_choice PROPERTIES LABELS unit TIMEOUT 120)
