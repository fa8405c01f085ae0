# The container image (docker/), label `container`: builds the images with
# docker/build-image.sh (cached layers; the first build compiles the project, ~20 minutes) and
# runs docker/test-image.sh (one container, then the compose cluster with a worker stopped
# mid-job). Not part of the default run: it skips (exit 77) unless FOSLS_CONTAINER_TESTS=1,
#   FOSLS_CONTAINER_TESTS=1 ctest --test-dir build -L container --output-on-failure
add_test(NAME container_image COMMAND ${CMAKE_CURRENT_LIST_DIR}/container_test.sh
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(container_image PROPERTIES LABELS container SKIP_RETURN_CODE 77
                                                TIMEOUT 5400 RUN_SERIAL TRUE)
