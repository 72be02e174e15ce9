# carom: the two commands a newcomer needs, each complete on a fresh Debian machine.
#   make run    install what running needs, build the tool, run the billiards break (examples/),
#               summarise it
#   make test   install what CI needs, then everything CI checks
# More: make bench (core benchmarks, optimised build), make bench-instructions (the engine's
# instructions a collision, counted by callgrind), make fuzz (the fuzz targets, 10 minutes
# each), make format, make lint (make lint-deep with the static analyzer), make clean.
# Browser playground: make playground (serve it; PORT=8080), make test-web, make bench-web.
# Python: make python (build the module and install it for Debian's python3).

SHELL := /bin/bash
.ONESHELL:
.SHELLFLAGS := -eu -o pipefail -c

# Debian packages, kept in one place. make run installs the missing ones of RUN_PACKAGES, what
# the release preset's carom_cli target and its run need: CLI11, nlohmann-json and fmt; Cairo,
# found with pkg-config, draws pictures and frames; the ffmpeg program encodes animations
# (tests/package/check_run_packages.cmake checks the list against what configuring needs).
RUN_PACKAGES := cmake ninja-build g++ nlohmann-json3-dev libcli11-dev libfmt-dev \
                libcairo2-dev pkg-config ffmpeg
# make test and the rest (`make deps`) install everything CI needs as well: the second compiler
# and its sanitizer runtimes, clang-format and clang-tidy, GoogleTest and Google Benchmark, the
# peers, and Open MPI (carom eos across ranks, tested under mpirun).
PACKAGES := $(RUN_PACKAGES) clang clang-format clang-tidy libclang-rt-14-dev \
            libgtest-dev libgmock-dev libbenchmark-dev libbox2d-dev libopenmpi-dev openmpi-bin \
            $(PYTHON_PACKAGES)

# make python: the module (pybind11, NumPy), its tests (pytest), GSD trajectories (gsd), carom.eos
# across MPI ranks (mpi4py) and the examples' plots (matplotlib), all from Debian; Debian's python3 imports what is installed under
# /usr/local/lib/python3.11/dist-packages.
PYTHON_PACKAGES := pybind11-dev python3-dev python3-numpy python3-pytest python3-gsd python3-mpi4py \
                   python3-matplotlib
PYTHON_PREFIX := /usr/local

RUN_PICTURE := build/two-moving-balls.svg
RUN_DIR := build/run
RUN_ANIMATION := $(RUN_DIR)/billiards-break.gif
CAROM := build/release/apps/carom/carom
# The scene loader's libFuzzer target: a bounded run in make test, a longer one in make fuzz.
FUZZER := build/fuzz/tests/fuzz/carom_scene_fuzz
FUZZ_SMOKE_SECONDS ?= 10

.PHONY: all deps run-deps run test test-long test-dev test-clang test-asan format-check bench format
.PHONY: lint clean
# make run prints what a person reads (the build's progress, the run's summary, where its files
# are), not the recipes' source.
.SILENT: deps run-deps run
.PHONY: wasm playground test-web bench-web
.PHONY: fuzz-build python python-deps

all: run

# Installs the packages of $(1) that are missing (as root), or prints the apt-get line that does
# and fails.
define install-missing
missing=$$(for p in $(1); do \
  dpkg-query -W -f='$${Status}\n' "$$p" 2>/dev/null | grep -q '^install ok installed$$' || echo "$$p"; \
done)
if [ -z "$$missing" ]; then exit 0; fi
if [ "$$(id -u)" = 0 ]; then
  echo "carom: installing missing Debian packages:" $$missing
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing
else
  echo "carom: missing Debian packages. Install them with:"
  echo "  sudo apt-get install -y" $$missing
  exit 1
fi
endef

deps:
	$(call install-missing,$(PACKAGES))

run-deps:
	$(call install-missing,$(RUN_PACKAGES))

python-deps:
	$(call install-missing,$(RUN_PACKAGES) $(PYTHON_PACKAGES))

# Builds the Python module (preset release) and installs it where Debian's python3 imports it (as
# root), or says how to use it from the build folder.
python: python-deps
	cmake --preset release >/dev/null
	cmake --build --preset release --target carom_python
	if [ "$$(id -u)" = 0 ]; then
	  cmake --install build/release --component python --prefix $(PYTHON_PREFIX) >/dev/null
	  cd /tmp && /usr/bin/python3 -c "import carom; print('carom for Python installed:', carom.__file__)"
	else
	  echo "Built build/release/python/carom. Use it with:"
	  echo "  PYTHONPATH=$$PWD/build/release/python python3"
	  echo "or install it as root: sudo make python"
	fi

run: run-deps
	echo "Building the carom tool (preset release, in build/release):"
	cmake --preset release >/dev/null
	cmake --build --preset release --target carom_cli
	mkdir -p $(RUN_DIR)
	$(CAROM) run examples/billiards.json --every 0.1 --stats \
	  --frames $(RUN_DIR)/billiards-frames.csv --events $(RUN_DIR)/billiards-events.jsonl \
	  --save $(RUN_DIR)/billiards-end.json
	$(CAROM) sweep --a 0,0,1 --va 6,2 --b 8,3,1.5 --vb -4,-1 --svg $(RUN_PICTURE) >/dev/null
	echo
	echo "The billiards break (examples/billiards.json) until every ball rests:"
	echo "  frames (positions, velocities every 0.1 s):  $(RUN_DIR)/billiards-frames.csv"
	echo "  every contact and change of motion, as JSON lines: $(RUN_DIR)/billiards-events.jsonl"
	echo "  the end state, a scene to continue from:     $(RUN_DIR)/billiards-end.json"
	echo "The tutorial's two balls, drawn:               $(RUN_PICTURE) (open it in a browser)"
	$(CAROM) render examples/billiards.json --animate $(RUN_ANIMATION) --until 8 --trails 0.25
	echo "The billiards break, animated:                 $(RUN_ANIMATION) (open it in a browser)"
	echo "More scenes in examples/; try: $(CAROM) run examples/periodic-gas.json --until 1 --stats"
	echo "Install the tool, library and examples: cmake --install build/release --prefix ~/.local"

# The browser tests need chromium (and emscripten, node-acorn, npm); .ci/run installs them.
TEST_WEB := $(if $(wildcard /usr/bin/chromium),test-web)

# Each compiler builds everything once: g++ in test-dev (the suite at full speed, benchmarks'
# smoke runs included), clang++ in test-clang-asan (the suite again under ASan + UBSan; the
# kernels optimised in test-clang-kernels, beside the browser tests). Timings
# and reasoning: docs/design.md, "CI time".
test: deps test-dev test-clang-asan format-check checks-beside-web
	echo "make test: all checks passed"

# Two lanes side by side, each keeping a core busy: clang-tidy, the optimised clang kernels and
# the fuzzers' bounded runs in one; the browser tests (which wait for what a page shows, never for
# a fixed time, so that a loaded machine slows them without failing them) and the
# ThreadSanitizer test in the other (docs/design.md, "CI time"). Each lane's output is shown whole
# when it ends.
.PHONY: checks-beside-web lint-then-fuzz web-then-tsan
checks-beside-web:
	$(MAKE) --no-print-directory -j2 --output-sync=target lint-then-fuzz web-then-tsan

lint-then-fuzz:
	$(MAKE) --no-print-directory lint
	$(MAKE) --no-print-directory test-clang-kernels
	$(MAKE) --no-print-directory fuzz-smoke

web-then-tsan:
	$(if $(TEST_WEB),$(MAKE) --no-print-directory test-web)
	$(MAKE) --no-print-directory test-tsan

test-dev:
	cmake --preset dev
	cmake --build --preset dev
	ctest --preset dev

test-clang:
	cmake --preset clang
	cmake --build --preset clang
	ctest --preset clang

test-asan:
	cmake --preset asan
	cmake --build --preset asan
	ctest --preset asan

# clang++ -Werror over the library, the tool and the tests, the suite run under AddressSanitizer +
# UndefinedBehaviorSanitizer: test-clang and test-asan in one build. The benchmarks and peers are
# left to test-dev (g++ -Werror, their smoke runs) and make test-clang: under the sanitizers they
# cost a fifth of the stage and test nothing the library's suite does not (decision 0039).
.PHONY: test-clang-asan
test-clang-asan:
	cmake --preset clang-asan
	cmake --build --preset clang-asan
	ctest --preset clang-asan

# Sanitizers keep clang from vectorising, so the libraries and the kernels' tests are also built
# optimised (preset clang): there -Wpass-failed checks that the batch kernels' vectorisation
# pragmas hold, and the tests check the vectorised batch (core) and the pair kernel (world)
# against the scalar query bit for bit.
.PHONY: test-clang-kernels
test-clang-kernels:
	cmake --preset clang >/dev/null
	cmake --build --preset clang --target carom_core_tests carom_world_kernel_tests
	build/clang/tests/carom_core_tests --gtest_brief=1
	build/clang/tests/carom_world_kernel_tests --gtest_brief=1

# ThreadSanitizer on the threads test: independent worlds stepped on several threads at once.
.PHONY: test-tsan
test-tsan:
	cmake --preset tsan
	cmake --build --preset tsan --target carom_thread_tests
	ctest --preset tsan

# libFuzzer (clang, the fuzz preset). The time-of-impact target starts from the committed seeds
# in tests/fuzz/corpus/toi and keeps what it finds in build/fuzz/corpus/toi, so the committed
# corpus changes only by hand. make fuzz runs each target for FUZZ_SECONDS.
FUZZ_SECONDS ?= 600
# The bounded runs in make test start from a fixed seed, so that each tries the same inputs in the
# same order on every machine (a fresh clone has only the committed seeds): a failure there is a
# regression, reproducible with the same command, not a new find that happened to come up this
# time. make fuzz and the fuzz-* targets explore with a new seed each run; what they find goes
# into the committed corpus with a test (docs/guarantees.md, section 11).
FUZZ_SMOKE_SEED ?= 1
TOI_FUZZ_SMOKE_SECONDS ?= 10
TOI_FUZZ := build/fuzz/tests/fuzz/carom_toi_fuzz
.PHONY: fuzz-smoke fuzz fuzz-toi-build fuzz-toi-smoke fuzz-toi
fuzz: fuzz-toi

fuzz-toi-build:
	cmake --preset fuzz >/dev/null
	cmake --build --preset fuzz --target carom_toi_fuzz
	mkdir -p build/fuzz/corpus/toi

fuzz-toi-smoke: fuzz-toi-build
	$(TOI_FUZZ) -seed=$(FUZZ_SMOKE_SEED) -max_total_time=$(TOI_FUZZ_SMOKE_SECONDS) -print_final_stats=1 \
	  -artifact_prefix=build/fuzz/ build/fuzz/corpus/toi tests/fuzz/corpus/toi

fuzz-toi: fuzz-toi-build
	$(TOI_FUZZ) -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 -artifact_prefix=build/fuzz/ \
	  build/fuzz/corpus/toi tests/fuzz/corpus/toi

# The World driven by random API calls (tests/fuzz/world_fuzz.cpp), from the committed seeds in
# tests/fuzz/corpus/world. Each smoke run's length is a variable, so CI time can be tuned.
WORLD_FUZZ := build/fuzz/tests/fuzz/carom_world_fuzz
# The smoke run is a fixed number of inputs (about 8 s alone on CI's machine), so that it tries
# the same ones everywhere, however fast the machine; the time is a cap, which make test's load
# beside the browser tests can reach first.
WORLD_FUZZ_SMOKE_RUNS ?= 6000
WORLD_FUZZ_SMOKE_SECONDS ?= 40
WORLD_FUZZ_FLAGS := -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=build/fuzz/
.PHONY: fuzz-world-build fuzz-world-smoke fuzz-world
fuzz: fuzz-world

fuzz-world-build:
	cmake --preset fuzz >/dev/null
	cmake --build --preset fuzz --target carom_world_fuzz
	mkdir -p build/fuzz/corpus/world

fuzz-world-smoke: fuzz-world-build
	$(WORLD_FUZZ) -seed=$(FUZZ_SMOKE_SEED) -runs=$(WORLD_FUZZ_SMOKE_RUNS) \
	  -max_total_time=$(WORLD_FUZZ_SMOKE_SECONDS) $(WORLD_FUZZ_FLAGS) \
	  build/fuzz/corpus/world tests/fuzz/corpus/world

fuzz-world: fuzz-world-build
	$(WORLD_FUZZ) -max_total_time=$(FUZZ_SECONDS) $(WORLD_FUZZ_FLAGS) \
	  build/fuzz/corpus/world tests/fuzz/corpus/world

# The long versions of the tests that make test runs short (CAROM_LONG_TESTS=1 un-skips them).
test-long: deps
	cmake --preset release >/dev/null
	cmake --build --preset release
	CAROM_LONG_TESTS=1 ctest --preset release

fuzz-build:
	cmake --preset fuzz >/dev/null
	cmake --build --preset fuzz --target carom_scene_fuzz

# New inputs the fuzzer finds go to build/fuzz/corpus; the committed seeds stay as they are.
# make test's bounded runs: the three targets built at once, then the three fuzzers side by side
# (each is one process on one core; the world's run is a fixed number of inputs, the other two
# a fixed time), the logs of the two in the background shown when they end.
fuzz-smoke:
	cmake --preset fuzz >/dev/null
	cmake --build --preset fuzz --target carom_toi_fuzz carom_scene_fuzz carom_world_fuzz
	mkdir -p build/fuzz/corpus/toi build/fuzz/corpus/scene build/fuzz/corpus/world
	$(WORLD_FUZZ) -seed=$(FUZZ_SMOKE_SEED) -runs=$(WORLD_FUZZ_SMOKE_RUNS) \
	  -max_total_time=$(WORLD_FUZZ_SMOKE_SECONDS) $(WORLD_FUZZ_FLAGS) \
	  build/fuzz/corpus/world tests/fuzz/corpus/world > build/fuzz/world-smoke.log 2>&1 &
	world_fuzz=$$!
	$(TOI_FUZZ) -seed=$(FUZZ_SMOKE_SEED) -max_total_time=$(FUZZ_SMOKE_SECONDS) -print_final_stats=1 \
	  -artifact_prefix=build/fuzz/ build/fuzz/corpus/toi tests/fuzz/corpus/toi > build/fuzz/toi-smoke.log 2>&1 &
	toi_fuzz=$$!
	$(FUZZER) -seed=$(FUZZ_SMOKE_SEED) -max_total_time=$(FUZZ_SMOKE_SECONDS) -timeout=10 \
	  -rss_limit_mb=2048 -artifact_prefix=build/fuzz/ build/fuzz/corpus/scene tests/fuzz/corpus/scene
	toi_status=0; wait $$toi_fuzz || toi_status=$$?
	world_status=0; wait $$world_fuzz || world_status=$$?
	cat build/fuzz/toi-smoke.log build/fuzz/world-smoke.log
	[ $$toi_status = 0 ] && exit $$world_status || exit $$toi_status

fuzz: fuzz-build
	mkdir -p build/fuzz/corpus/scene
	$(FUZZER) -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	  -artifact_prefix=build/fuzz/ build/fuzz/corpus/scene tests/fuzz/corpus/scene

format-check:
	git ls-files -- '*.hpp' '*.cpp' | xargs clang-format --dry-run -Werror

bench: deps
	cmake --preset release >/dev/null
	cmake --build --preset release --target carom_bench
	build/release/bench/carom_bench

format:
	git ls-files -- '*.hpp' '*.cpp' | xargs clang-format -i

# make lint (in make test): .clang-tidy's checks without the clang static analyzer, which costs
# about two thirds of clang-tidy's time (docs/design.md, "CI time"); without
# bugprone-reserved-identifier, a sixth of what is left (it looks at every name the standard
# library's headers declare, to report the few in carom's own code, which has none); and, in the
# files that include CLI11, without performance-unnecessary-value-param: it analyses every
# function CLI11's headers define (10 s a file for the include alone, where the file's own code
# costs about 10 s with every other check). make lint-deep runs every check on every file.
LINT_CHECKS ?= -clang-analyzer-*,-bugprone-reserved-identifier
LINT_CLI11_CHECKS ?= -performance-unnecessary-value-param
# Its compile commands come from the lint preset, configured only (no build): the translation units
# the build compiles, the unity groups among them (a group's sources checked once each, in the
# group, the headers they share parsed once: a quarter of the time file by file, decision 0039)
# and the files outside them. make lint-deep checks file by file (the lint-deep preset), with
# every check. A unity file's own #includes of .cpp files are the point of it, not a finding.
LINT_PRESET ?= lint
lint: deps
	cmake --preset $(LINT_PRESET) >/dev/null
	# clang-tidy counts the warnings it suppressed in system headers on stderr; only findings matter.
	# One unit per clang-tidy: its cost per unit varies tenfold, so handing them out one by one
	# keeps both cores busy to the end.
	python3 -c 'import json, sys; print("\n".join(e["file"] for e in json.load(open(sys.argv[1]))))' \
	  build/$(LINT_PRESET)/compile_commands.json | xargs -P 2 -n 1 sh -c '
	  checks="$(LINT_CHECKS)"
	  sources="$$0"
	  case "$$0" in *.cxx)
	    checks="$${checks:+$$checks,}-bugprone-suspicious-include"
	    sources=$$(sed -n "s/^#include \"\(.*\)\"$$/\1/p" "$$0");;
	  esac
	  if [ -n "$(LINT_CLI11_CHECKS)" ] && grep -q "<CLI/CLI.hpp>" $$sources; then
	    checks="$${checks:+$$checks,}$(LINT_CLI11_CHECKS)"
	  fi
	  exec clang-tidy -p build/$(LINT_PRESET) --quiet --checks="$$checks" "$$0"' \
	  2> >(grep -v 'warnings generated' >&2)

.PHONY: lint-deep
lint-deep:
	$(MAKE) lint LINT_PRESET=lint-deep LINT_CHECKS= LINT_CLI11_CHECKS=

# ---- the browser playground (web/) ----
# Debian's emscripten needs NODE_PATH to find acorn for its optimiser, and a writable cache: the
# packaged one (prebuilt system libraries) when it is writable, otherwise one under build/.
WASM_ENV = NODE_PATH=/usr/share/nodejs $$([ -w "$$(em-config CACHE 2>/dev/null)" ] || echo EM_CACHE=$(CURDIR)/build/em-cache)
WEB_SITE := build/wasm/web/site
WEB_NODE_MODULES := web/node_modules/.package-lock.json

wasm:
	for tool in emcc node npm; do
	  command -v $$tool >/dev/null || { echo "carom: $$tool is missing; install it with:"; \
	    echo "  sudo apt-get install -y emscripten node-acorn nodejs npm"; exit 1; }
	done
	env $(WASM_ENV) cmake --preset wasm >/dev/null
	env $(WASM_ENV) cmake --build --preset wasm

# playwright-core, exactly as web/package-lock.json pins it (node_modules is not committed).
$(WEB_NODE_MODULES): web/package.json web/package-lock.json
	cd web && npm ci --no-audit --no-fund

# Serves the playground on http://127.0.0.1:$(PORT) with web/serve.mjs (Node's standard library
# only): make playground PORT=8000 when 8080 is taken.
PORT ?= 8080
playground: wasm
	node web/serve.mjs $(WEB_SITE) $(PORT)

# End-to-end tests in Debian's chromium; screenshots go to build/web-test-output/. The native
# carom CLI is the reference the "Two moving balls" page is compared with: the dev build's, which
# make test has built already (its results are bit-identical to release's: -ffp-contract=off).
# Two test files run at once, each with its own browser and server: a page spends most of its
# time waiting (loading, animation frames), so one file at a time leaves more than a core idle.
WEB_TEST_CAROM := build/dev/apps/carom/carom
test-web: deps wasm $(WEB_NODE_MODULES)
	test -x /usr/bin/chromium || { echo "carom: chromium is missing: sudo apt-get install -y chromium"; exit 1; }
	cmake --preset dev >/dev/null
	cmake --build --preset dev --target carom_cli
	cd web && CAROM_CLI=$(CURDIR)/$(WEB_TEST_CAROM) node --test --test-concurrency=2 tests/

# Frame times of "Many balls" with 10⁴ balls (and 10³ beside it) in headless chromium.
bench-web: wasm $(WEB_NODE_MODULES)
	node web/bench/frame_times.mjs 10000 1000

clean:
	rm -rf build

# The long validation of the hard-disk measurements: runs `carom eos` and `carom gas`
# for a few minutes and writes docs/validation.md with tables and plots (docs/figures/validation).
.PHONY: validate
validate: deps
	cmake --preset release >/dev/null
	cmake --build --preset release --target carom_cli
	tests/science/validate.sh $(CAROM)

# carom beside Box2D 2.4 and Chipmunk 7 on the same scenes: every case in a process of
# its own, a few minutes in all; writes docs/peers.md. A peer that is not installed is left out.
PACKAGES += libchipmunk-dev
.PHONY: bench-peers
bench-peers: deps
	cmake --preset release >/dev/null
	cmake --build --preset release --target carom_peers
	build/release/bench/peers/carom_peers report --out docs/peers.md --command "make bench-peers"

# Instructions a collision of the engine on the hard-disk gas, counted by callgrind: the same on
# every run of the same binary, whatever the host is doing (tools/perf/README.md;
# docs/decisions/0024-judging-speed-on-shared-hosts.md). About 15 s a gas of 10⁴ disks, 2
# minutes at 10⁵.
INSTRUCTION_GASES ?= 10000 0.3 10000 0.6
.PHONY: bench-instructions
bench-instructions: deps
	$(MAKE) --no-print-directory deps PACKAGES=valgrind
	cmake --preset release >/dev/null
	cmake --build --preset release --target carom_world_gas_probe
	tools/perf/instructions_per_collision.sh build/release/tools/perf/carom_world_gas_probe $(INSTRUCTION_GASES)

# The soak test (not in make test): 10⁸ collisions of the hard-disk gas at packing 0.6,
# audited every 10⁶, with energy, momentum and memory checked (tests/soak/world_soak.cpp). Minutes.
SOAK_ARGS ?= 10000 0.6 1e8 1e6
.PHONY: soak
soak: deps
	cmake --preset release >/dev/null
	cmake --build --preset release --target carom_world_soak
	build/release/tests/soak/carom_world_soak $(SOAK_ARGS)
