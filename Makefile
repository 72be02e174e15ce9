# carom: the two commands a newcomer needs, each complete on a fresh Debian machine.
#   make run    install what is missing, build, run the default two-ball case, draw it
#   make test   install what is missing, then everything CI checks
# More: make bench (core benchmarks, optimised build), make format, make lint, make clean.

SHELL := /bin/bash
.ONESHELL:
.SHELLFLAGS := -eu -o pipefail -c

# Debian packages carom builds with. Kept in one place; `make deps` installs the missing ones.
PACKAGES := cmake ninja-build g++ clang clang-format clang-tidy \
            libgtest-dev libgmock-dev libbenchmark-dev \
            nlohmann-json3-dev libcli11-dev libfmt-dev libbox2d-dev
# carom render: Cairo draws the pictures and frames (found with pkg-config); ffmpeg encodes.
PACKAGES += libcairo2-dev pkg-config ffmpeg

RUN_PICTURE := build/two-moving-balls.svg
RUN_ANIMATION := build/billiards-break.gif
CAROM := build/release/apps/carom/carom

.PHONY: all deps run test test-long test-dev test-clang test-asan format-check bench format lint clean

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
	$(CAROM) sweep --a 0,0,1 --va 6,2 --b 8,3,1.5 --vb -4,-1 --svg $(RUN_PICTURE)
	echo
	echo "The picture of this case is in $(RUN_PICTURE) (open it in a browser)."
	$(CAROM) render examples/billiards.json --animate $(RUN_ANIMATION) --until 2.5 --trails 0.25
	echo "The billiards break, animated, is in $(RUN_ANIMATION) (open it in a browser)."

test: deps test-dev test-clang test-asan format-check lint
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
