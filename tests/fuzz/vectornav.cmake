# VN-300 front-end: arbitrary bytes into the "vn" StreamDecoder and the reply parser.
navfuse_add_fuzzer(vn_stream_fuzzer
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/vectornav/vn_stream_fuzzer.cpp
  LIBS navfuse_vectornav
  CORPUS ${CMAKE_CURRENT_LIST_DIR}/vectornav/corpus)
