# Wall time of the gap diagnosis on a 4000 s, 1 Hz, four-channel log.
if(TARGET driftlab_host_gap)
  driftlab_add_bench(gap_bench SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/gap_bench.cpp LIBS driftlab_host_gap)
endif()
