# SPDX-License-Identifier: MIT
# The two commands of the README:
#   make run   installs missing Debian packages, builds, and opens the editor (WORLD=... optional)
#   make test  installs missing Debian packages, builds, and runs the whole CTest suite
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
CTEST_FLAGS ?=
WORLD ?=

.PHONY: all deps configure build run test test-asan format format-check clean

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

# the core and its tests under AddressSanitizer + UndefinedBehaviorSanitizer; the long physics
# runs (label "physics") stay in the optimized `make test`
test-asan:
	$(MAKE) test BUILD=build-asan CTEST_FLAGS="-LE physics" CMAKE_FLAGS="-DCMAKE_BUILD_TYPE=Debug \
	  -DLAMINA_SANITIZE='address;undefined' -DLAMINA_BUILD_EDITOR=OFF -DLAMINA_BUILD_HEADLESS=OFF \
	  $(CMAKE_FLAGS)"

SOURCES = $(shell git ls-files '*.cpp' '*.h')

format:
	clang-format -i $(SOURCES)

format-check:
	clang-format --dry-run --Werror $(SOURCES)

clean:
	rm -rf build build-asan
