# facet: set-up, build and test. A new user needs two commands: `make run` and `make test`.
#
#   make deps           install the Debian 12 packages that are missing (apt-get; root or sudo)
#   make build          configure a Release build in build/ (once) and build it
#   make run            deps + build, then render the built-in islands world to islands.png
#   make test           deps + build, then run every test with ctest
#   make test-sanitize  the tests under ASan+UBSan (build-asan/), the threaded raster tests
#                       under TSan (build-tsan/); also separately: make test-asan, make test-tsan
#   make test-fuzz      the libFuzzer targets (tests/fuzz/*_fuzz.cpp, clang, build-fuzz/), each for
#                       FUZZ_SECONDS (default 60) from a scratch copy of tests/fuzz/corpus/NAME/;
#                       then FUZZ_MUTATIONS (default 1000) seeded mutations of each sample format
#   make install        cmake --install build --prefix $(PREFIX)   (PREFIX=/usr/local by default):
#                       the libraries, the program and the Python module (docs/python.md)
#   make clean          remove the build trees and islands.png

# Debian 12 packages the build and the tests need. A new dependency is added here.
PACKAGES := build-essential cmake pkg-config libglm-dev libpng-dev libtbb-dev libcli11-dev \
  libgtest-dev libstb-dev libassimp-dev assimp-testmodels glmark2-data clang libclang-rt-dev \
  libopenal-dev libsdl2-dev libimgui-dev libhwy-dev libopenexr-dev xdotool xvfb python3 \
  pybind11-dev python3-dev python3-numpy python3-pytest python3-pip python3-setuptools \
  python3-wheel python3-venv python3-distributed libtinygltf-dev nlohmann-json3-dev \
  libmeshoptimizer-dev libdraco-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri ninja-build

BUILD_DIR ?= build
ASAN_DIR ?= build-asan
TSAN_DIR ?= build-tsan
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_MUTATIONS ?= 1000
JOBS ?= $(shell nproc)
# The Python the module is built for and tested with: Debian's, which has the packages above
# (NumPy, pytest), even where another python3 comes first on the PATH.
PYTHON ?= /usr/bin/python3
PREFIX ?= /usr/local
SCENE_IMAGE ?= islands.png
# ctest -E regex for the tests the ASan run leaves out (the Release run has them all):
# - the viewer driven by xdotool under Xvfb (each waits on a window and real time, several
#   seconds apiece under ASan; the viewer's frame code runs under ASan in View.* without one);
# - the assimp fence's own tests: a child forked while other threads run can block on ASan's
#   allocator locks, which a plain build does not have, until the fence's time limit;
# - the sweeps of assimp's sample files, importing each and rendering each through the program
#   (assimp itself is not instrumented, and a fenced read can wait out the same time limit);
#   facet's side of them runs under ASan in ImportMutations.* and ToneMapping.*.
ASAN_EXCLUDE_REGEX ?= ^ViewInput\.|^ImportFence\.|^AssimpTestModels/|^CliToneMappingSampleModels\.
# ctest -R regex for the tests that run under ThreadSanitizer: the threaded raster tests (the
# TSan build compiles only their files: tests/CMakeLists.txt).
TSAN_TEST_REGEX ?= ^(Determinism|SimdTargets|Occlusion)\.|^DebugView\.ImagesAreTheSameForAnyThreadCount$$

# Every build tree is made with Ninja: it compiles a target's files while the libraries it links
# are still being built, where the Makefile generator waits for each library's last (and often
# longest) file with a core idle.
GENERATOR := -G Ninja

# The sanitizer and fuzz builds optimize less (-O1) and keep only line tables (-g1): that is
# enough for a report's stack trace with file and line, and builds about 40 % faster than
# RelWithDebInfo's -O2 -g, with the same test time (ASan build 233 s instead of ~400 s, suite 70 s
# both ways, on this project's 2-core machine).
CHECKED_BUILD_FLAGS := $(GENERATOR) -DCMAKE_BUILD_TYPE=RelWithDebInfo '-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG'

# Any sanitizer report fails the run, with a stack trace.
ASAN_RUNTIME_OPTIONS := halt_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1
UBSAN_RUNTIME_OPTIONS := halt_on_error=1:print_stacktrace=1
LSAN_RUNTIME_OPTIONS := suppressions=$(CURDIR)/cmake/lsan.supp:print_suppressions=0
TSAN_RUNTIME_OPTIONS := halt_on_error=1:second_deadlock_stack=1:suppressions=$(CURDIR)/cmake/tsan.supp

SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := run
# Targets run one after another; each build is parallel inside (cmake --build -j).
.NOTPARALLEL:
MAKEFLAGS += --no-print-directory
.PHONY: help deps build run test test-sanitize test-asan test-tsan test-fuzz install clean

help:
	@sed -n '1,/^$$/p' $(firstword $(MAKEFILE_LIST)) | sed 's/^# \{0,1\}//'

deps:
	@command -v dpkg-query >/dev/null || { \
	  echo "deps: not a Debian system; install these (or your system's equivalents): $(PACKAGES)" >&2; \
	  exit 1; }
	@missing=""; \
	for package in $(PACKAGES); do \
	  status=$$(dpkg-query -W -f='$${Status}' "$$package" 2>/dev/null || true); \
	  [ "$$status" = "install ok installed" ] || missing="$$missing $$package"; \
	done; \
	if [ -z "$$missing" ]; then echo "deps: all Debian packages are installed"; exit 0; fi; \
	sudo=""; \
	if [ "$$(id -u)" -ne 0 ]; then \
	  command -v sudo >/dev/null || { echo "deps: run as root or install sudo; missing:$$missing" >&2; exit 1; }; \
	  sudo=sudo; \
	fi; \
	echo "deps: installing:$$missing"; \
	$$sudo apt-get update; \
	$$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $$missing

build: deps
	@if [ ! -f $(BUILD_DIR)/CMakeCache.txt ]; then \
	  cmake -S . -B $(BUILD_DIR) $(GENERATOR) -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=$(PYTHON); \
	fi
	cmake --build $(BUILD_DIR) -j$(JOBS)

run: build
	@start=$$(date +%s%N); \
	$(BUILD_DIR)/facet render --scene islands -o $(SCENE_IMAGE); \
	ms=$$(( ($$(date +%s%N) - start) / 1000000 )); \
	echo "Image: $$(realpath $(SCENE_IMAGE))"; \
	printf 'Took %d.%03d s wall clock (start-up, render and writing the PNG)\n' $$((ms / 1000)) $$((ms % 1000))

test: build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j2 --no-tests=error

test-sanitize: test-asan test-tsan

# The whole suite under AddressSanitizer + UndefinedBehaviorSanitizer, with static libraries
# (the Release build's are shared), so the install test covers both kinds. The Python module is
# off (a sanitized extension needs the sanitizer's runtime preloaded into the Python interpreter).
# The OpenGL twin is off in every checked build: Mesa's own allocations are LeakSanitizer noise,
# and its tests repeat the Release run's. Each ctest test here is a whole GoogleTest suite
# (cmake/GTestSuites.cmake), so the regex below matches suite names.
test-asan: export ASAN_OPTIONS := $(ASAN_RUNTIME_OPTIONS)
test-asan: export UBSAN_OPTIONS := $(UBSAN_RUNTIME_OPTIONS)
test-asan: export LSAN_OPTIONS := $(LSAN_RUNTIME_OPTIONS)
test-asan: deps
	@if [ ! -f $(ASAN_DIR)/CMakeCache.txt ]; then \
	  cmake -S . -B $(ASAN_DIR) $(CHECKED_BUILD_FLAGS) -DFACET_SANITIZE=address \
	    -DBUILD_SHARED_LIBS=OFF -DFACET_BUILD_PYTHON=OFF -DFACET_BUILD_GL=OFF; \
	fi
	cmake --build $(ASAN_DIR) -j$(JOBS)
	ctest --test-dir $(ASAN_DIR) -E '$(ASAN_EXCLUDE_REGEX)' --output-on-failure -j2 --no-tests=error

# Only the threaded raster tests under ThreadSanitizer, so only the test program is built.
test-tsan: export TSAN_OPTIONS := $(TSAN_RUNTIME_OPTIONS)
test-tsan: deps
	@if [ ! -f $(TSAN_DIR)/CMakeCache.txt ]; then \
	  cmake -S . -B $(TSAN_DIR) $(CHECKED_BUILD_FLAGS) -DFACET_SANITIZE=thread \
	    -DFACET_INSTALL_TEST=OFF -DFACET_BUILD_PYTHON=OFF -DFACET_BUILD_GL=OFF; \
	fi
	cmake --build $(TSAN_DIR) -j$(JOBS) --target facet_tests
	ctest --test-dir $(TSAN_DIR) -R '$(TSAN_TEST_REGEX)' --output-on-failure -j2 --no-tests=error

# Each fuzz target runs on a scratch copy of its seed corpus, so the inputs it discovers do not
# grow the repository; a crashing input is kept as $(FUZZ_DIR)/crash-NAME-* and fails the run
# with the fuzzer's whole report.
test-fuzz: deps
	@if [ ! -f $(FUZZ_DIR)/CMakeCache.txt ]; then \
	  CXX=clang++ cmake -S . -B $(FUZZ_DIR) $(CHECKED_BUILD_FLAGS) -DFACET_FUZZ=ON \
	    -DFACET_BUILD_TESTS=OFF -DFACET_INSTALL_TEST=OFF -DFACET_BUILD_PYTHON=OFF -DFACET_BUILD_GL=OFF; \
	fi
	cmake --build $(FUZZ_DIR) -j$(JOBS) --target facet_fuzz
	@for fuzzer in $(FUZZ_DIR)/*_fuzz; do \
	  name=$$(basename "$$fuzzer" _fuzz); \
	  scratch=$$(mktemp -d); \
	  trap 'rm -rf "$$scratch"' EXIT; \
	  if [ -d tests/fuzz/corpus/$$name ]; then cp -R tests/fuzz/corpus/$$name/. "$$scratch"/; fi; \
	  echo "fuzz: $$name for $(FUZZ_SECONDS) s (log: $(FUZZ_DIR)/$$name.log)"; \
	  if ! "$$fuzzer" -max_total_time=$(FUZZ_SECONDS) -timeout=10 -print_final_stats=1 \
	      -artifact_prefix=$(FUZZ_DIR)/crash-$$name- "$$scratch" >$(FUZZ_DIR)/$$name.log 2>&1; then \
	    cat $(FUZZ_DIR)/$$name.log; echo "fuzz: $$name FAILED" >&2; exit 1; \
	  fi; \
	  grep -E '^(Done|stat::number_of_executed_units|stat::peak_rss_mb)' $(FUZZ_DIR)/$$name.log || true; \
	  rm -rf "$$scratch"; \
	done
	@# The seeded mutations of every sample format (tests/import_mutations_test.cpp), longer than
	@# in `make test`: FUZZ_MUTATIONS per format, in the Release build (0: none, as CI, whose
	@# `make test` runs 50 of each).
	@if [ "$(FUZZ_MUTATIONS)" -gt 0 ]; then \
	  $(MAKE) build && \
	  FACET_MUTATIONS=$(FUZZ_MUTATIONS) $(BUILD_DIR)/tests/facet_tests --gtest_filter='*ImportMutations*'; \
	fi

install: build
	cmake --install $(BUILD_DIR) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD_DIR) $(ASAN_DIR) $(TSAN_DIR) $(FUZZ_DIR) build-python $(SCENE_IMAGE)
