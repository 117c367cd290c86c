# dispkin — the two set-up commands are `make demo` and `make test` (see README.md).
# Each installs whatever is missing first (scripts/install-deps.sh).

BUILD ?= build/cmake
VENV  ?= .venv
JOBS  ?= $(shell nproc)
CMAKE_FLAGS ?=
export CMAKE_BUILD_PARALLEL_LEVEL ?= $(JOBS)

.PHONY: all deps build python test test-cpp test-python demo bench sanitize sweep fuzz clean

all: build

deps:
	@scripts/install-deps.sh

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DDISPKIN_BUILD_TESTS=ON \
	  -DDISPKIN_BUILD_BENCHMARKS=ON $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# The Python package, built by scikit-build-core exactly as `pip install .` does (the build
# requirements are already in the venv, so no isolated build environment is downloaded).
python: deps
	$(VENV)/bin/python -m pip install -q --no-build-isolation .

test-cpp: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

test-python: python
	$(VENV)/bin/python -m pytest -q tests/python

test: test-cpp test-python

# The demo job lives in DEMO_DIR/job.yaml (written from the built-in one the first time): edit it
# and run `make demo` again.
DEMO_DIR ?= demo
demo: python
	$(VENV)/bin/dispkin demo -o $(DEMO_DIR)

# The C++ suites under AddressSanitizer and UndefinedBehaviorSanitizer (any finding fails).
# EIGEN_MALLOC_ALREADY_ALIGNED=1: under ASan Eigen would switch to its own aligned allocator
# (it assumes nothing of the sanitizer's malloc), while the Debian KDL library, built without
# ASan, frees with plain free(): KDL solvers whose Eigen members are created in our code then
# fail with "free on address which was not malloc()-ed". ASan's malloc is 16-byte aligned on
# x86-64 like glibc's, so keeping Eigen on plain malloc is correct and matches the library.
SANITIZE_BUILD ?= build/sanitize
sanitize: deps
	cmake -S . -B $(SANITIZE_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDISPKIN_BUILD_TESTS=ON -DDISPKIN_SWEEP_COUNT=1000 \
	  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -DEIGEN_MALLOC_ALREADY_ALIGNED=1"
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  DISPKIN_TEST_COUNT=2000 ctest --output-on-failure -j $(JOBS) -E find_package_consumer

# libFuzzer targets (tests/fuzz, clang from Debian via scripts/install-fuzz-deps.sh, which only
# this target calls): built with ASan + UBSan in FUZZ_BUILD, each run for FUZZ_SECONDS from its
# seed corpus (scripts/run-fuzzers.sh; FUZZERS selects targets). Any finding fails.
FUZZ_BUILD ?= build/fuzz
FUZZ_SECONDS ?= 60
FUZZERS ?=
fuzz: deps
	@scripts/install-fuzz-deps.sh
	cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
	  -DDISPKIN_BUILD_FUZZERS=ON -DDISPKIN_BUILD_TESTS=OFF -DDISPKIN_BUILD_EXAMPLES=OFF -DDISPKIN_BUILD_BENCHMARKS=OFF
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzzers
	FUZZ_BUILD=$(FUZZ_BUILD) FUZZ_SECONDS=$(FUZZ_SECONDS) scripts/run-fuzzers.sh $(FUZZERS)

# The sweeps at 10⁷ cases per family (issue 9): their own Release build directory, only the
# tests labelled "sweep" (tests/CMakeLists.txt). Hours on a 2-core machine; SWEEP_COUNT scales it.
SWEEP_BUILD ?= build/sweep
SWEEP_COUNT ?= 10000000
sweep: deps
	cmake -S . -B $(SWEEP_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DDISPKIN_BUILD_TESTS=ON -DDISPKIN_BUILD_BENCHMARKS=OFF \
	  -DDISPKIN_BUILD_EXAMPLES=OFF -DDISPKIN_SWEEP_COUNT=$(SWEEP_COUNT)
	cmake --build $(SWEEP_BUILD) -j $(JOBS) --target dispkin_sweep_tests dispkin_serial_tests
	cd $(SWEEP_BUILD) && ctest --output-on-failure -j $(JOBS) -L sweep

bench: build
	$(BUILD)/benchmarks/dispkin_benchmarks --benchmark_min_time=0.2

clean:
	rm -rf build
