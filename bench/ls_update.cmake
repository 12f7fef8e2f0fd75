# LsWindow update and evaluation cost on the host (bench/ls_update_bench.cpp).
driftlab_add_bench(ls_update_bench SOURCES "${CMAKE_CURRENT_LIST_DIR}/ls_update_bench.cpp" LIBS driftlab_fw_core)
