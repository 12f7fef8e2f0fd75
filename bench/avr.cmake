# The real firmware in simavr: real-time factor of the AVR target and the firmware's cycle budget
# (bench/avr_bench.cpp, docs/avr-in-the-loop.md). Needs driftlab_sim_avr (libsimavr-dev) and the ELF (avr-g++).
if(TARGET driftlab_sim_avr)
  driftlab_add_bench(avr_bench SOURCES "${CMAKE_CURRENT_LIST_DIR}/avr_bench.cpp" LIBS driftlab_sim_avr)
endif()
