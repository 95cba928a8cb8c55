# Fusion loop: measurements with fuzzed times (jumps, gaps, clocks) through FusionRunner and the
# filter; the counts must add up at the end.
navfuse_add_fuzzer(time_fault_fuzz
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fusion/time_fault_fuzz.cpp
  LIBS navfuse_apps
  CORPUS ${CMAKE_CURRENT_LIST_DIR}/fusion/corpus
  RUNS 20000)
