# Thin wrapper over CMake/CTest so a fresh clone needs two commands:
#   make reproduce-all   every figure, table and the report under build/
#   make test            the default test tier (everything but the `develop` label)
BUILD   ?= build
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: deps configure build test test-develop test-sanitize bench clean

deps:
	@tools/ensure_deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) --log-level=WARNING

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

# Default tier: unit (`fast`), `stability`, `cli`, and the reproduction checks at the CI tier.
test: build
	@cd $(BUILD) && ctest -LE develop --output-on-failure -j$(JOBS) --timeout 1500

# Long checks (1e8-step energy balance, converged references).
test-develop: build
	@cd $(BUILD) && ctest -L develop --output-on-failure -j$(JOBS)

# The fast tests again under AddressSanitizer + UndefinedBehaviorSanitizer (Debug, own tree).
test-sanitize: deps
	@cmake -S . -B $(BUILD)-asan -DCMAKE_BUILD_TYPE=Debug -DSPRINGBLOCK_SANITIZE=ON \
	  -DSPRINGBLOCK_BUILD_REPRODUCE=OFF -DSPRINGBLOCK_BUILD_BENCH=OFF > /dev/null
	@cmake --build $(BUILD)-asan -j$(JOBS)
	@cd $(BUILD)-asan && ctest -L fast --output-on-failure -j$(JOBS)

bench: build
	@cmake --build $(BUILD) --target bench-report

clean:
	@rm -rf $(BUILD) $(BUILD)-asan

# ---- reproduce-all (reproduction section) ------------------------------------------------------
# Configure (Release), build, run every figure/table target with progress and ETA, then compare
# with the published numbers. TIER=paper|quick|smoke (default quick), METHOD=event|rk4.
TIER   ?= quick
METHOD ?= event
.PHONY: reproduce-all
reproduce-all:
	@if [ -x tools/ensure_deps.sh ]; then tools/ensure_deps.sh; fi
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DSPRINGBLOCK_TIER=$(TIER) \
	  -DSPRINGBLOCK_REPRO_METHOD=$(METHOD) --log-level=WARNING
	@cmake --build $(BUILD) -j$(JOBS)
	@/usr/bin/python3 tools/reproduce_all.py $(BUILD) figures report
