# Eq. 1 drift fit: time to fit 4000 and 10^6 samples (prints figures, never fails on time).
if(TARGET driftlab_host_fit)
  driftlab_add_bench(fit_bench SOURCES ${CMAKE_CURRENT_LIST_DIR}/fit_bench.cpp LIBS driftlab_host_fit)
endif()
