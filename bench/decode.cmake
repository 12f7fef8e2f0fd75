# Protocol v1 encode/decode throughput (frames per second); prints figures only.
driftlab_add_bench(decode_bench SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/decode_bench.cpp LIBS driftlab_proto)
