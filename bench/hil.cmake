# Host-in-the-loop speed: real-time factor of the fig3 preset and cost per ADC conversion (bench/hil_bench.cpp).
if(TARGET driftlab_sim)
  driftlab_add_bench(hil_bench SOURCES "${CMAKE_CURRENT_LIST_DIR}/hil_bench.cpp" LIBS driftlab_sim)
endif()
