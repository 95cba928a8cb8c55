# libFuzzer targets for the research-data text readers (imutxt, rtklib): one source, built once
# per reader (tests/fuzz/text_readers/text_reader_fuzz.cpp).
navfuse_add_fuzzer(navfuse_imutxt_fuzz
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/text_readers/text_reader_fuzz.cpp
  LIBS navfuse_imutxt navfuse_rtklib
  CORPUS ${CMAKE_CURRENT_LIST_DIR}/text_readers/corpus_imutxt)
navfuse_add_fuzzer(navfuse_rtklib_fuzz
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/text_readers/text_reader_fuzz.cpp
  LIBS navfuse_imutxt navfuse_rtklib
  CORPUS ${CMAKE_CURRENT_LIST_DIR}/text_readers/corpus_rtklib)
if(NAVFUSE_FUZZ)
  target_compile_definitions(navfuse_imutxt_fuzz PRIVATE NAVFUSE_FUZZ_FORMAT=1)
  target_compile_definitions(navfuse_rtklib_fuzz PRIVATE NAVFUSE_FUZZ_FORMAT=2)
endif()
