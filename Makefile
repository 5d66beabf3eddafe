# SPDX-License-Identifier: MIT
# The two commands of the README:
#   make run   installs missing Debian packages, builds, and opens the editor (WORLD=... optional)
#   make test  installs missing Debian packages, builds, and runs the whole CTest suite
#   make install PREFIX=/usr/local installs the programs, the worlds and the Python package
#   make bench builds the benchmarks in BENCH_BUILD (optimized, no editor) and prints medians
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
CTEST_FLAGS ?=
WORLD ?=
BENCH_BUILD ?= build-bench
BENCH_FLAGS ?= --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

PREFIX ?= /usr/local

.PHONY: all deps configure build run test test-asan install bench bench-python accuracy peers format \
        format-check clean

all: build

deps:
	@bash cmake/setup-deps.sh

configure: deps
	cmake -S . -B $(BUILD) -G Ninja $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD) -j$(JOBS)

run: build
	$(BUILD)/bin/lamina $(WORLD)

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) $(CTEST_FLAGS)

# bin/lamina, bin/lamina-headless, share/lamina/worlds and the Python package lamina in
# lib/pythonX.Y/dist-packages under PREFIX (through sudo when PREFIX is not writable)
install: build
	@if mkdir -p $(PREFIX) 2>/dev/null && [ -w $(PREFIX) ]; then \
	  cmake --install $(BUILD) --prefix $(PREFIX); \
	else sudo cmake --install $(BUILD) --prefix $(PREFIX); fi

# the core and its tests under AddressSanitizer + UndefinedBehaviorSanitizer (Debug, at -O1 with
# assertions on: cmake/LaminaOptions.cmake); the long physics
# runs (label "physics") and the benchmark smoke run (label "bench") stay in the optimized
# `make test` (the benchmarks are not even built here)
test-asan:
	$(MAKE) test BUILD=build-asan CTEST_FLAGS="-LE 'physics|bench'" CMAKE_FLAGS="-DCMAKE_BUILD_TYPE=Debug \
	  -DLAMINA_SANITIZE='address;undefined' -DLAMINA_BUILD_EDITOR=OFF -DLAMINA_BUILD_HEADLESS=OFF \
	  -DLAMINA_BUILD_BENCHMARKS=OFF -DLAMINA_BUILD_PYTHON=OFF -DLAMINA_BUILD_PHYSICS_TESTS=OFF \
	  -DLAMINA_BUILD_PEERS=OFF \
	  $(CMAKE_FLAGS)"

# timings from one run: every benchmark repeated, the console shows medians (and the spread);
# BENCH_FLAGS="--benchmark_filter=BoxStack" for a subset
bench: deps
	cmake -S . -B $(BENCH_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLAMINA_BUILD_EDITOR=OFF \
	  -DLAMINA_BUILD_HEADLESS=OFF -DLAMINA_BUILD_TESTS=OFF -DLAMINA_BUILD_BENCHMARKS=ON $(CMAKE_FLAGS)
	cmake --build $(BENCH_BUILD) -j$(JOBS) --target lamina_bench
	$(BENCH_BUILD)/bin/lamina_bench $(BENCH_FLAGS)

# what calling simulate from Python costs against C++ on ATHLETE (tests/bench/python_overhead.py)
bench-python: build
	PYTHONPATH=$(BUILD)/python /usr/bin/python3 tests/bench/python_overhead.py
	PYTHONPATH=$(BUILD)/python /usr/bin/python3 tests/bench/python_overhead.py --quickstep

# docs/accuracy.md with its plots, runs.csv and runs.json in docs/accuracy/: every scene of
# worlds/accuracy at steps 1e-5 ... 1e-2 s with the exact, Newton and QuickStep solvers, on every
# core; with MuJoCo's and Bullet's runs of docs/accuracy/peers (`make peers`) on the same plots
PEER_RUNS = docs/accuracy/peers/runs.json
accuracy: build
	$(BUILD)/bin/lamina-headless accuracy --out docs/accuracy --markdown docs/accuracy.md \
	  $(if $(wildcard $(PEER_RUNS)),--peers $(PEER_RUNS))

# the accuracy scenes through MuJoCo and Bullet (tests/bench/peers): installs Debian's
# libmujoco-dev and libbullet-dev, builds lamina-peers and writes docs/accuracy/peers; then
# `make accuracy` plots those runs beside Lamina's. Never part of `make test`.
peers: deps
	@bash cmake/setup-deps.sh peers
	cmake -S . -B $(BUILD) -G Ninja -DLAMINA_BUILD_PEERS=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j$(JOBS) --target lamina-peers
	$(BUILD)/bin/lamina-peers --out docs/accuracy/peers

SOURCES = $(shell git ls-files '*.cpp' '*.h')

format:
	clang-format -i $(SOURCES)

format-check:
	clang-format --dry-run --Werror $(SOURCES)

clean:
	rm -rf build build-asan $(BENCH_BUILD)
