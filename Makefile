# carom: the two commands a newcomer needs, each complete on a fresh Debian machine.
#   make run    install what is missing, build, run the billiards break (examples/), summarise it
#   make test   install what is missing, then everything CI checks
# More: make bench (core benchmarks, optimised build), make fuzz (the scene loader, 10 minutes),
# make format, make lint, make clean.

SHELL := /bin/bash
.ONESHELL:
.SHELLFLAGS := -eu -o pipefail -c

# Debian packages carom builds with. Kept in one place; `make deps` installs the missing ones.
PACKAGES := cmake ninja-build g++ clang clang-format clang-tidy \
            libgtest-dev libgmock-dev libbenchmark-dev \
            nlohmann-json3-dev libcli11-dev libfmt-dev libbox2d-dev libclang-rt-14-dev

RUN_PICTURE := build/two-moving-balls.svg
RUN_DIR := build/run
CAROM := build/release/apps/carom/carom
# The scene loader's libFuzzer target: a bounded run in make test, a longer one in make fuzz.
FUZZER := build/fuzz/tests/fuzz/carom_scene_fuzz
FUZZ_SMOKE_SECONDS := 20
FUZZ_SECONDS := 600

.PHONY: all deps run test test-long test-dev test-clang test-asan format-check bench format lint clean \
        fuzz fuzz-smoke fuzz-build

all: run

deps:
	missing=$$(for p in $(PACKAGES); do \
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

run: deps
	cmake --preset release >/dev/null
	cmake --build --preset release --target carom_cli
	mkdir -p $(RUN_DIR)
	$(CAROM) run examples/billiards.json --until 10 --stats \
	  --frames $(RUN_DIR)/billiards-frames.csv --events $(RUN_DIR)/billiards-events.jsonl \
	  --save $(RUN_DIR)/billiards-end.json
	$(CAROM) sweep --a 0,0,1 --va 6,2 --b 8,3,1.5 --vb -4,-1 --svg $(RUN_PICTURE) >/dev/null
	echo
	echo "The billiards break (examples/billiards.json), 10 s of it:"
	echo "  frames (positions, velocities every 0.1 s):  $(RUN_DIR)/billiards-frames.csv"
	echo "  every contact, as JSON lines:                $(RUN_DIR)/billiards-events.jsonl"
	echo "  the end state, a scene to continue from:     $(RUN_DIR)/billiards-end.json"
	echo "The tutorial's two balls, drawn:               $(RUN_PICTURE) (open it in a browser)"
	echo "More scenes in examples/; try: $(CAROM) run examples/periodic-gas.json --until 1 --stats"

test: deps test-dev test-clang test-asan fuzz-smoke format-check lint
	echo "make test: all checks passed"

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

# The long versions of the tests that make test runs short (CAROM_LONG_TESTS=1 un-skips them).
test-long: deps
	cmake --preset release >/dev/null
	cmake --build --preset release
	CAROM_LONG_TESTS=1 ctest --preset release

fuzz-build:
	cmake --preset fuzz >/dev/null
	cmake --build --preset fuzz --target carom_scene_fuzz

# New inputs the fuzzer finds go to build/fuzz/corpus; the committed seeds stay as they are.
fuzz-smoke: fuzz-build
	mkdir -p build/fuzz/corpus
	$(FUZZER) -max_total_time=$(FUZZ_SMOKE_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	  -artifact_prefix=build/fuzz/ build/fuzz/corpus tests/fuzz/corpus/scene

fuzz: fuzz-build
	mkdir -p build/fuzz/corpus
	$(FUZZER) -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	  -artifact_prefix=build/fuzz/ build/fuzz/corpus tests/fuzz/corpus/scene

format-check:
	git ls-files -- '*.hpp' '*.cpp' | xargs clang-format --dry-run -Werror

bench: deps
	cmake --preset release >/dev/null
	cmake --build --preset release --target carom_bench
	build/release/bench/carom_bench

format:
	git ls-files -- '*.hpp' '*.cpp' | xargs clang-format -i

lint: deps
	cmake --preset dev >/dev/null
	# clang-tidy counts the warnings it suppressed in system headers on stderr; only findings matter.
	git ls-files -- 'src/*.cpp' 'apps/*.cpp' \
	  | xargs -P 2 -n 4 clang-tidy -p build/dev --quiet 2> >(grep -v 'warnings generated' >&2)

clean:
	rm -rf build
