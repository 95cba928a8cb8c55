# VN-300 front-end: framing + decoding throughput on a corrupted 200 Hz IMU+INS / 5 Hz GNSS log.
navfuse_add_benchmark(vn_decode_bench SOURCES ${CMAKE_CURRENT_LIST_DIR}/vectornav_decode_bench.cpp LIBS navfuse_vectornav)
