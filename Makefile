# riser_sim: the README's commands. Everything installs what it needs first.
SHELL := /bin/bash
ROOT := $(abspath .)
WS := $(ROOT)/.ws
SETUP := set +u; source $(WS)/devel/setup.bash

.PHONY: deps fuzz-deps build check test format test-sanitize fuzz fuzz-replay sim bench bench-baseline soak many_risers figures demo modes clean

# The Debian packages (ROS 1 from Debian itself; list in tools/install_deps.sh), installed when missing.
deps:
	@missing=$$(tools/install_deps.sh --missing); if [ -n "$$missing" ]; then \
	  echo "installing: $$missing"; SUDO=""; [ "$$(id -u)" = 0 ] || SUDO=sudo; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y --no-install-recommends $$missing; \
	fi

build: deps
	@tools/build.sh -j2 all riser_sim_benches

# The edit-test loop: build the core + CLI without catkin and run their gtests (~2 min cold, seconds after).
# CHECK_ARGS go to ctest, e.g. make check CHECK_ARGS='-R statics'.
check: deps
	@tools/check.sh $(CHECK_ARGS)

# Every test: gtests, rostests, the core's gtests under sanitizers (docs/hardening.md). The fuzzer's seeds and
# regressions replay as gtests; RISER_SIM_FUZZ_SECONDS=30 make test adds a fuzz run.
test: deps
	@tools/test.sh

# Applies .clang-format (clang-format 14) to every C++ file; make test fails on a file that differs.
format: deps
	@tools/format.sh

# The core's and the CLI's gtests under ASan + UBSan (part of `make test` too; docs/hardening.md).
test-sanitize: deps
	@tools/test_sanitize.sh

# libFuzzer on the scene loader for FUZZ_SECONDS (default 120); crashers -> out/fuzz/crashers.
FUZZ_SECONDS ?= 120
fuzz: fuzz-deps
	@$(MAKE) --no-print-directory -f test/fuzz/Makefile run FUZZ_SECONDS=$(FUZZ_SECONDS)

# The fuzzer over its seeds and regressions once, no mutation.
fuzz-replay: fuzz-deps
	@$(MAKE) --no-print-directory -f test/fuzz/Makefile replay

# clang-14 and its sanitizer/libFuzzer runtime are part of deps (the sanitizer build of make test uses them).
fuzz-deps: deps

sim: build
	@$(SETUP); bench/paper_table1.py --sim

# Every benchmark; its tables go into docs/benchmarks.md (bench/update_docs.py; RISER_SIM_BENCH_DOCS=0: not).
bench: build
	@$(SETUP); bench/run_all.sh

# The shipped scenes' step cost -> out/bench/step_cost_baseline.csv, which make bench compares against (~15 s).
bench-baseline: build
	@$(WS)/devel/lib/riser_sim/riser_sim_bench_step_cost --save-baseline

# An hour of simulated time of the J-lay scene through /clock: memory, step time, error bounds
# -> out/soak/soak.csv, soak.txt (docs/benchmarks.md, "Soak"). ~15-20 min.
soak: build
	@bench/soak.sh

# How many risers keep real time, as nodes and as nodelets -> out/bench/many_risers.csv. ~10-20 min.
many_risers: build
	@bench/many_risers.sh both

# Lowest 4 mode shapes of the shipped paper scenes -> out/figures/modes_<scene>.png (docs/modal.md).
modes: build
	@for s in paper_jlay_170m paper_table1; do \
	  if [ -f config/scenes/$$s.yaml ]; then \
	    /usr/bin/python3 scripts/plot_modes.py --cli $(WS)/devel/lib/riser_sim/riser_sim_cli \
	      --scene config/scenes/$$s.yaml --modes 4 || exit 1; \
	  fi; \
	done

# The paper's section 4 runs and plots -> out/figures/*.csv, *.png, numbers.txt (docs/figures.md).
figures: build
	@RISER_SIM_WS=$(WS) tools/figures.sh

demo:
	@tools/demo.sh

clean:
	rm -rf $(WS) out
