# Allan-family deviations: octave OADEV on 10^6 and 10^7 samples on one core (bench/allan_bench.cpp).
if(TARGET driftlab_host_stats)
  driftlab_add_bench(allan_bench SOURCES "${CMAKE_CURRENT_LIST_DIR}/allan_bench.cpp" LIBS driftlab_host_stats)
endif()
