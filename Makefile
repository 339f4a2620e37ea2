# momentlab: every target installs what it needs (Debian 12), configures and builds.
# Quick start: `make demo`, `make test`.

SHELL := /bin/bash
BUILD ?= build/release
JOBS ?= 2
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

APT_PACKAGES := g++ cmake make libeigen3-dev libgmp-dev nlohmann-json3-dev libcli11-dev \
                libgtest-dev libbenchmark-dev libcdd-dev libsiconos-numerics-dev

.PHONY: all deps build demo test bench clean

all: build

# Install the Debian packages that are missing (needs root or sudo; no-op when all present).
deps:
	@missing=$$(for p in $(APT_PACKAGES); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	    echo "Installing:" $$missing; \
	    SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	    $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing >/dev/null; \
	fi

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j$(JOBS)

demo: build
	@bash examples/demo.sh $(BUILD)/momentlab

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

bench: build
	$(BUILD)/bench/bench_cone
	$(BUILD)/bench/bench_contact

clean:
	rm -rf build out
