# MIP framing and framing+decoding throughput on a CV7-style 0x80/0x82 stream with 1% corrupted
# bytes (tests/bench/mip_bench.cpp).
navfuse_add_benchmark(navfuse_mip_bench SOURCES ${CMAKE_CURRENT_LIST_DIR}/mip_bench.cpp LIBS navfuse_mip)
# The same stream written to a file and framed from it, for tests/bench/mip_vendor_compare.sh
# (MicroStrain's own parser on the same bytes). A plain program: it needs no Google Benchmark.
add_executable(navfuse_mip_bench_stream ${CMAKE_CURRENT_LIST_DIR}/mip_bench_stream.cpp)
target_link_libraries(navfuse_mip_bench_stream PRIVATE navfuse_mip navfuse_build_flags)
