# UM220-INS front-end: sentence framing + decoding throughput on a mixed, 1 %-corrupted log.
navfuse_add_benchmark(unicore_decode_bench SOURCES ${CMAKE_CURRENT_LIST_DIR}/unicore_decode_bench.cpp
                      LIBS navfuse_unicore)
