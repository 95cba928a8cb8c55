# navfuse: two commands for a fresh Debian 12 machine.
#   make demo   install what is missing, build the navfuse binary, replay the bundled VN-300 sample
#   make test   install what is missing, build, run every test through ctest
# Also: make bench (Google Benchmark programs), make sanitize (ASan+UBSan build, tests and
# fuzz targets under clang), make build, make clean.

BUILD      ?= build/release
SAN_BUILD  ?= build/sanitize
JOBS       ?= $(shell nproc)
# Warnings are errors in CI (CI=true is set there).
WERROR     ?= $(if $(CI),ON,OFF)
CTEST_ARGS ?=

.PHONY: all deps configure build test demo bench sanitize clean

all: build

deps:
	@scripts/install-deps.sh

$(BUILD)/build.ninja: | deps
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DNAVFUSE_WERROR=$(WERROR)

configure: deps $(BUILD)/build.ninja

build: configure
	cmake --build $(BUILD) -j $(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

# The demo needs the navfuse binary only, not the tests and benchmarks `build` makes (a fraction
# of the targets: minutes instead of a quarter of an hour on two cores).
demo: configure
	cmake --build $(BUILD) -j $(JOBS) --target navfuse
	@scripts/demo.sh $(BUILD)

bench: configure
	cmake --build $(BUILD) -j $(JOBS) --target navfuse_benchmarks
	@scripts/bench.sh $(BUILD)

# ASan+UBSan with clang, plus the libFuzzer targets run for a fixed number of iterations.
# Long Monte-Carlo scenario tests (label "scenario") run in `make test` only: under the
# sanitizers they take too long to be useful and exercise the same code as the short tests.
# The code under test is built at -O1 with line tables only (what ASan's documentation suggests;
# stack traces keep file and line) and the test code at -O0: clang with the sanitizers spent most
# of CI's time generating code for test bodies at -O2 -g.
# Warnings are errors in the gcc build (`make test` in CI); here clang's findings are the
# sanitizers' reports, so its own warning set does not fail the run.
sanitize: deps
	CC=clang CXX=clang++ cmake -S . -B $(SAN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" -DNAVFUSE_TEST_OPT_FLAGS=-O0 \
	  -DNAVFUSE_SANITIZE=ON -DNAVFUSE_FUZZ=ON -DNAVFUSE_BENCH=OFF -DNAVFUSE_WERROR=OFF
	cmake --build $(SAN_BUILD) -j $(JOBS)
	cd $(SAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j $(JOBS) -LE scenario $(CTEST_ARGS)

clean:
	rm -rf build
