# Reading crafted captures: time against size (bench/capture_bench.cpp).
if(TARGET driftlab_host_io)
  driftlab_add_bench(capture_bench SOURCES "${CMAKE_CURRENT_LIST_DIR}/capture_bench.cpp" LIBS driftlab_host_io)
endif()
