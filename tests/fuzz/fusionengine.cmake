# libFuzzer target: arbitrary bytes through the FusionEngine StreamDecoder (in random chunks)
# and the device-control command handler, checking the counter invariants.
navfuse_add_fuzzer(navfuse_fe_fuzzer
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fusionengine/fe_decoder_fuzz.cpp
  LIBS navfuse_fusionengine
  CORPUS ${CMAKE_CURRENT_LIST_DIR}/fusionengine/corpus)
