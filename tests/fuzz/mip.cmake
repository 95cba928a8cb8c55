# libFuzzer target for the MIP front-end: arbitrary bytes into the StreamDecoder, the aiding
# handler and the command responder; counter invariants checked (tests/fuzz/mip_fuzz.cpp).
navfuse_add_fuzzer(navfuse_mip_fuzz
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/mip/mip_fuzz.cpp
  LIBS navfuse_mip
  CORPUS ${CMAKE_CURRENT_LIST_DIR}/mip/corpus)
