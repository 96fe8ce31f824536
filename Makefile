# Thin wrapper over CMake/CTest so a fresh clone needs two commands:
#   make reproduce-all   every figure, table and the report under build/, at the paper's statistics
#   make test            the default test tier, including every published number and claim checked
#                        at the same tier (both read the same results: run either first)
#   make docs            the documentation site, build/docs/html/index.html
# TIER=paper|quick|smoke chooses the statistics of both (default paper: the paper's 20
# repetitions; quick and smoke are for development and resolve less, see the report).
# MPIRUN="mpirun -np 4" runs each reproduction target over MPI ranks (the same numbers).
BUILD   ?= build
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
TIER    ?= paper
METHOD  ?= event
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
CONFIG  = $(CMAKE_FLAGS) -DSPRINGBLOCK_TIER=$(TIER) -DSPRINGBLOCK_REPRO_METHOD=$(METHOD)

.PHONY: deps configure build test test-develop test-sanitize bench clean reproduce-all studies docs

deps:
	@tools/ensure_deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CONFIG) --log-level=WARNING > /dev/null

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

# Default tier: unit (`fast`), `stability`, `cli`, `report`, and the reproduction checks (every
# published number and claim) at TIER. The reproduction fixtures build the same results as
# reproduce-all, so after it they cost nothing.
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

# The documentation site, build/docs/html/index.html: builds only the command and the Python
# module it runs and documents, then Sphinx (warnings as errors) and the link and image check.
docs: configure
	@cmake --build $(BUILD) --target docs -j$(JOBS)

clean:
	@rm -rf $(BUILD) $(BUILD)-asan

# Builds only the simulator and the reproduction drivers, runs every figure/table target with
# one line per target and an ETA (full logs under $(BUILD)/logs/), compares with the published
# numbers, draws the figures and writes the report.
# The tools run as modules from this directory (python3 -m tools.<name>: tools/__init__.py).
# The clock starts before configure, so the run record's total is the whole command's.
# A build tree without a CMake cache is a fresh one: the record says so (the README's cost of a
# fresh clone), rather than guessing it from how much the build compiled.
# MPIRUN="mpirun -np 4" starts every target with that launcher: rank 0 deals the target's repetitions
# to the ranks and alone writes its document, with the numbers of one process.
reproduce-all:
	@t0=$$(date +%s.%N) && fresh=$$(test -f $(BUILD)/CMakeCache.txt || echo --fresh-build) && \
	  $(MAKE) --no-print-directory configure && \
	  /usr/bin/python3 -m tools.reproduce_all $(BUILD) --jobs $(JOBS) --started-at $$t0 $$fresh \
	    $(if $(MPIRUN),--mpirun "$(MPIRUN)")

# The optional studies (expensive, slow to change): run at TIER and commit their documents under
# paper/data/, which the figures and the report read.
studies: configure
	@/usr/bin/python3 -m tools.reproduce_all $(BUILD) --jobs $(JOBS) --studies
