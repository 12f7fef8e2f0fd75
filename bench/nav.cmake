# Navigation speed: nav's four variants over an hour at 0.1 s rows (bench/nav_bench.cpp).
if(TARGET driftlab_host_nav)
  driftlab_add_bench(nav_bench SOURCES "${CMAKE_CURRENT_LIST_DIR}/nav_bench.cpp" LIBS driftlab_host_nav)
endif()
