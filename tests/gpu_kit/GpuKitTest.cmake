# The GPU kit's test (tests/gpu_kit/gpu_kit_test.sh, docs/GPU.md), added to the top-level
# folder at its end (bench/CMakeLists.txt defers it there), once CTest is on.
if(BUILD_TESTING AND TARGET ivshadow_bench)
  add_test(NAME gpu_kit.packs_unpacks_and_passes_quick
           COMMAND ${PROJECT_SOURCE_DIR}/tests/gpu_kit/gpu_kit_test.sh ${PROJECT_SOURCE_DIR}
                   ${CMAKE_BINARY_DIR} ${CMAKE_BINARY_DIR}/test-output/gpu_kit)
  # Its quick run keeps two test processes busy; its packing takes about a minute.
  set_tests_properties(gpu_kit.packs_unpacks_and_passes_quick PROPERTIES
                       LABELS gl PROCESSORS 2 TIMEOUT 900 SKIP_RETURN_CODE 77)
endif()
