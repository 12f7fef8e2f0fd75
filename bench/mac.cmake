# The command authenticator's candidates on the ATmega328P in simavr: cycles, flash and RAM of each
# (bench/mac_bench.cpp, docs/security.md "Authenticated commands"). Needs driftlab_sim_avr and the AVR images.
if(TARGET driftlab_sim_avr)
  driftlab_add_bench(mac_bench SOURCES "${CMAKE_CURRENT_LIST_DIR}/mac_bench.cpp" LIBS driftlab_sim_avr)
endif()
