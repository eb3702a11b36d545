# riser_sim: the README's commands. Everything installs what it needs first.
SHELL := /bin/bash
ROOT := $(abspath .)
WS := $(ROOT)/.ws
SETUP := set +u; source $(WS)/devel/setup.bash

.PHONY: deps build test sim bench figures demo clean

deps:
	@scripts/install_deps.sh

build: deps
	@scripts/build.sh -j2

test: deps
	@scripts/test.sh

sim: build
	@$(SETUP); bench/paper_table1.py --sim

bench: build
	@$(SETUP); bench/run_all.sh

demo:
	@scripts/demo.sh

clean:
	rm -rf $(WS) out
