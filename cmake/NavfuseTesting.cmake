# navfuse_add_test(NAME SOURCES a.cpp b.cpp LIBS lib1 lib2 [LABELS l1 l2])
# One GoogleTest executable whose tests ctest discovers at test time.
include(GoogleTest)
# The shared captures (../shared beside the checkout by default): tests that read them skip when
# the folder is missing. A checkout elsewhere (a git worktree, a CI cache) points here with
# -DNAVFUSE_SHARED_DIR=/path/to/shared.
set(NAVFUSE_SHARED_DIR "${PROJECT_SOURCE_DIR}/../shared" CACHE PATH "folder of the shared captures")
# Test code is compiled with its own optimisation level, after the build type's flags (the last -O
# wins): the code under test, in the libraries, keeps the build type's level. Test bodies are
# mostly GoogleTest macros, whose code generation at -O3 made the test files most of the build
# time (a typical one: 11 s at -O3, 6 s at -O1; under clang + ASan -O2 -g 76 s, -O0 16 s).
# x86-64 floating point does not change with the level (no -ffast-math, no FMA contraction).
set(NAVFUSE_TEST_OPT_FLAGS "-O1" CACHE STRING "optimisation flags of test code (not of the code under test)")
separate_arguments(_navfuse_test_opt UNIX_COMMAND "${NAVFUSE_TEST_OPT_FLAGS}")
function(navfuse_add_test name)
  cmake_parse_arguments(T "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_compile_options(${name} PRIVATE ${_navfuse_test_opt})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main navfuse_build_flags)
  target_compile_definitions(${name} PRIVATE
    NAVFUSE_SHARED_DIR="${NAVFUSE_SHARED_DIR}"
    NAVFUSE_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    NAVFUSE_BINARY_DIR="${PROJECT_BINARY_DIR}")
  gtest_discover_tests(${name} DISCOVERY_MODE PRE_TEST DISCOVERY_TIMEOUT 60
                       PROPERTIES LABELS "${T_LABELS}")
endfunction()

# navfuse_add_benchmark(NAME SOURCES ... LIBS ...): a Google Benchmark program run by `make bench`.
function(navfuse_add_benchmark name)
  if(NOT NAVFUSE_BENCH)
    return()
  endif()
  cmake_parse_arguments(B "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${B_SOURCES})
  target_link_libraries(${name} PRIVATE ${B_LIBS} benchmark::benchmark benchmark::benchmark_main navfuse_build_flags)
  set_property(GLOBAL APPEND PROPERTY NAVFUSE_BENCHMARKS ${name})
endfunction()

# navfuse_add_fuzzer(NAME SOURCES ... LIBS ... CORPUS dir): a libFuzzer target, built only with
# NAVFUSE_FUZZ (clang), run for a fixed number of iterations as a ctest test labelled "fuzz".
function(navfuse_add_fuzzer name)
  if(NOT NAVFUSE_FUZZ)
    return()
  endif()
  cmake_parse_arguments(F "" "CORPUS;RUNS" "SOURCES;LIBS" ${ARGN})
  if(NOT F_RUNS)
    set(F_RUNS 200000)
  endif()
  add_executable(${name} ${F_SOURCES})
  target_compile_options(${name} PRIVATE -fsanitize=fuzzer)
  target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  target_link_libraries(${name} PRIVATE ${F_LIBS} navfuse_build_flags)
  # libFuzzer writes new inputs into the first corpus folder: keep that one in the build tree so
  # the seed corpus in the repo is only read.
  set(work ${CMAKE_CURRENT_BINARY_DIR}/${name}_corpus)
  file(MAKE_DIRECTORY ${work})
  add_test(NAME ${name} COMMAND ${name} -runs=${F_RUNS} -seed=1 -max_len=4096 ${work} ${F_CORPUS})
  set_tests_properties(${name} PROPERTIES LABELS fuzz)
endfunction()
