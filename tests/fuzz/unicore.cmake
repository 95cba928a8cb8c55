# UM220-INS front-end: arbitrary bytes into the "unicore" StreamDecoder (one feed and chunked),
# the reply reader and the single-line reply parser; counter invariants checked.
navfuse_add_fuzzer(unicore_stream_fuzzer
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/unicore/unicore_stream_fuzzer.cpp
  LIBS navfuse_unicore
  CORPUS ${CMAKE_CURRENT_LIST_DIR}/unicore/corpus)
