# momentlab: every target installs what it needs (Debian 12), configures and builds.
# Quick start: `make demo`, `make test`.

SHELL := /bin/bash
BUILD ?= build/release
JOBS ?= 2
PYTHON := /usr/bin/python3
# ccache: the pip install's build (tests/python/pip_install.sh) compiles the objects of the release
# build again, and `make demo` then `make test` build the same things; paths are hashed relative to
# the checkout (CCACHE_BASEDIR), so build directories share entries.
CCACHE := -DCMAKE_CXX_COMPILER_LAUNCHER=ccache
export CCACHE_BASEDIR := $(CURDIR)
export CCACHE_NOHASHDIR := 1
# Unity builds: each target's sources compiled in batches (CMake's UNITY_BUILD), so the headers
# they share (Eigen, CLI11, nlohmann-json) are parsed and their inline functions compiled once a
# batch rather than once a file (tools/build_times.sh compares the two). Every tree `make`
# configures is a unity build; a tree configured by hand is not unless asked
# (-DCMAKE_UNITY_BUILD=ON), and both must compile.
UNITY := -DCMAKE_UNITY_BUILD=ON
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release -DMOMENTLAB_PYTHON=ON -DPython_EXECUTABLE=$(PYTHON) $(CCACHE) $(UNITY)
# Build trees made here use Ninja (ninja-build): it compiles a target's objects while the layers
# it links are still being built, where make waits for each layer's link, so both cores stay busy.
# Existing trees keep the generator they were made with. (Expanded per command: `deps` may have
# just installed ninja.)
export CMAKE_GENERATOR = $(if $(shell command -v ninja 2>/dev/null),Ninja,Unix Makefiles)
# Where `make python` installs momentlab (the library, the CLI and the Python module).
PREFIX ?= /usr/local

APT_PACKAGES := g++ cmake make ccache libeigen3-dev libgmp-dev nlohmann-json3-dev libcli11-dev \
                libboost-dev libgtest-dev libbenchmark-dev libcdd-dev libsiconos-numerics-dev libcairo2-dev pkg-config libbox2d-dev libglpk-dev \
                clang libclang-rt-14-dev \
                python3-dev pybind11-dev python3-numpy python3-matplotlib python3-pytest python3-pip \
                python3-venv python3-setuptools python3-wheel ninja-build \
                emscripten nodejs chromium
# `make demo` installs only what it runs: first the packages of the library, the command line and
# the Python module's build, then, while those build, numpy, matplotlib and Emscripten.
DEMO_PACKAGES := g++ cmake make ccache ninja-build libeigen3-dev libgmp-dev nlohmann-json3-dev libcli11-dev \
                 libboost-dev libcairo2-dev pkg-config python3-dev pybind11-dev
DEMO_LATER_PACKAGES := python3-numpy python3-matplotlib emscripten nodejs
SAN_BUILD := build/asan
WEB_BUILD := build/web
# Emscripten's tools run on node without network (docs/web.md).
export NODE_PATH := /usr/share/nodejs
FUZZ_BUILD := build/fuzz
FUZZ_TARGETS := fuzz_scene_reader fuzz_labels_reader fuzz_cone fuzz_query
FUZZ_SECONDS ?= 600
SMOKE_SECONDS ?= 5

.PHONY: all deps build python web web-page test-web demo figures test test-release san-build test-sanitizers fuzz-build test-fuzz fuzz large-inputs instructions bench validate validate-long clean

all: build

# Install the Debian packages that are missing (needs root or sudo; no-op when all present).
# npm only when there is no npm command: Debian's nodejs has none, other nodejs builds bring theirs.
deps:
	@bash tools/install_packages.sh $(APT_PACKAGES) $$(command -v npm >/dev/null || echo npm)

$(BUILD)/CMakeCache.txt: Makefile | deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

# A tree `make demo` configured has no tests (their packages may be missing): turned on here.
build: deps $(BUILD)/CMakeCache.txt
	@grep -q '^MOMENTLAB_TESTS:BOOL=ON' $(BUILD)/CMakeCache.txt || cmake -S . -B $(BUILD) -DMOMENTLAB_TESTS=ON >/dev/null
	cmake --build $(BUILD) -j$(JOBS)

# `import momentlab` from any directory: the build installed into PREFIX (Debian's python3 reads
# PREFIX/lib/python3.X/dist-packages for /usr/local), then imported from / as a check.
python: build
	@SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	$$SUDO cmake --install $(BUILD) --prefix $(PREFIX) >/dev/null
	@cd / && env -u PYTHONPATH $(PYTHON) -c "import momentlab, sys; \
	a = momentlab.analyze(momentlab.Scene.from_file('$(CURDIR)/examples/figure-3-block-along-wall.json')); \
	assert a.query([0.0, -1.0, -0.5]) == ['ff']; \
	print('import momentlab:', momentlab.__file__)"

# The viewer (docs/web.md): out/web/index.html (one file: open it from disk) and out/web/momentlab.mjs
# (an ES module for node and pages), the library compiled to WebAssembly by Debian's Emscripten.
$(WEB_BUILD)/CMakeCache.txt:
	emcmake cmake -S . -B $(WEB_BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS=-fexceptions $(UNITY) >/dev/null

web: deps
	@$(MAKE) --no-print-directory web-page

# The same without installing packages (`make demo` installs its own).
web-page: $(WEB_BUILD)/CMakeCache.txt
	cmake --build $(WEB_BUILD) -j$(JOBS)
	@mkdir -p out/web
	@cp $(WEB_BUILD)/web/momentlab.mjs out/web/momentlab.mjs
	@$(PYTHON) web/build_page.py $(WEB_BUILD)/web/momentlab_classic.js examples out/web/index.html
	@echo "out/web/index.html: open it in a browser (from disk, no server needed); out/web/momentlab.mjs: the module"

# The module in node against the CLI, the page in Debian's chromium (playwright-core from npm,
# pinned in tests/web/package.json; never a downloaded browser).
test-web: web build
	@cd tests/web && { [ -d node_modules/playwright-core ] || npm install --no-audit --no-fund --loglevel=error; }
	MOMENTLAB_CLI=$(CURDIR)/$(BUILD)/momentlab node --no-experimental-fetch --test tests/web/test_module.mjs
	MOMENTLAB_CLI=$(CURDIR)/$(BUILD)/momentlab PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 node --test tests/web/test_page.mjs

# `make demo`: each part is built just before it is shown, the command line first (the library
# and the CLI only: no tests or benchmarks), then the Python module, then the WebAssembly page.
# Compiler output goes to DEMO_LOG; its last lines are shown when a build fails. `make test`
# builds everything.
DEMO_LOG := out/demo-build.log
DEMO_APT_LOG := out/demo-apt.log

demo:
	@set -eo pipefail; mkdir -p out; : > $(DEMO_LOG); \
	quiet() { "$$@" >>$(DEMO_LOG) 2>&1 || { tail -n 30 $(DEMO_LOG); echo "make demo: failed: $$* (the whole log: $(DEMO_LOG))"; exit 1; }; }; \
	took() { echo "   (built $$((SECONDS / 60)) min $$((SECONDS % 60)) s after the start; compiler output in $(DEMO_LOG))"; }; \
	first=$$(bash tools/install_packages.sh --missing $(DEMO_PACKAGES)); \
	later=$$(bash tools/install_packages.sh --missing $(DEMO_LATER_PACKAGES)); \
	bash tools/install_packages.sh $(DEMO_PACKAGES); \
	if [ -n "$$later" ]; then \
	    echo "== Installing in the background, for the Python and browser parts: $$later (log: $(DEMO_APT_LOG))"; \
	    bash tools/install_packages.sh $${first:+--updated} $$later > $(DEMO_APT_LOG) 2>&1 & later_pid=$$!; \
	fi; \
	echo "== Building the library and the command line into $(BUILD) (about 2 minutes on 2 cores)"; \
	[ -f $(BUILD)/CMakeCache.txt ] || quiet cmake -S . -B $(BUILD) -G Ninja $(CMAKE_FLAGS) -DMOMENTLAB_TESTS=OFF; \
	quiet cmake --build $(BUILD) -j$(JOBS) --target momentlab; took; \
	bash examples/demo.sh $(BUILD)/momentlab out; \
	echo; echo "== Building the Python module"; \
	quiet cmake --build $(BUILD) -j$(JOBS) --target _momentlab; took; \
	if [ -n "$$later" ]; then \
	    wait $$later_pid || { tail -n 30 $(DEMO_APT_LOG); echo "make demo: failed: installing $$later"; exit 1; }; \
	fi; \
	echo "== The same in Python: examples/python/tutorial.py (Figures 1-6 with matplotlib)"; \
	echo "   PYTHONPATH=$(BUILD)/python $(PYTHON) examples/python/tutorial.py out/python"; \
	PYTHONPATH=$(CURDIR)/$(BUILD)/python $(PYTHON) examples/python/tutorial.py out/python | sed 's/^/   /'; \
	echo; echo "== Building the browser viewer (WebAssembly, $(WEB_BUILD))"; \
	quiet $(MAKE) --no-print-directory web-page; took; \
	echo "== In the browser: open out/web/index.html (drag contacts and the force; pick a mode)"; \
	echo "   done in $$((SECONDS / 60)) min $$((SECONDS % 60)) s"

# The README's pictures (docs/figures/*.png), drawn by examples/demo.sh from the bundled examples
# with the command line alone.
FIGURES := figure-2 figure-3-modes figure-4b figure-5 figure-6 problem-peg problem-grasp
figures: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j$(JOBS) --target momentlab
	@tmp=$$(mktemp -d); bash examples/demo.sh $(BUILD)/momentlab $$tmp >/dev/null; \
	mkdir -p docs/figures; for f in $(FIGURES); do cp $$tmp/$$f.png docs/figures/; done; rm -rf $$tmp; ls docs/figures

# Every test: the suite in the release build, again under AddressSanitizer and
# UndefinedBehaviorSanitizer (any report fails) with clang, each fuzz target (built from the same
# sanitized objects) briefly on its corpus, and the WebAssembly module and page (node, chromium).
test: test-release test-sanitizers test-fuzz test-web

test-release: python
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

san-build: deps
	cmake --preset asan-ubsan $(CCACHE) $(UNITY) >/dev/null
	cmake --build $(SAN_BUILD) -j$(JOBS)

test-sanitizers: san-build
	cd $(SAN_BUILD) && ctest --output-on-failure -j$(JOBS)

$(FUZZ_BUILD)/CMakeCache.txt: | deps
	cmake --preset fuzz $(CCACHE) $(UNITY) >/dev/null

fuzz-build: deps $(FUZZ_BUILD)/CMakeCache.txt
	cmake --build $(FUZZ_BUILD) -j$(JOBS)

# The committed seed corpora are read, never written: new inputs go to a scratch directory.
# malloc_context_size=0: ASan keeps no allocation stacks (3x the executions per second). The smoke
# runs use the sanitizer build's targets; `make fuzz` builds optimised ones.
test-fuzz: san-build
	@for t in $(FUZZ_TARGETS); do \
	    scratch=$$(mktemp -d); \
	    echo "$$t: $(SMOKE_SECONDS) s on fuzz/corpus/$$t"; \
	    ASAN_OPTIONS=malloc_context_size=0 $(SAN_BUILD)/fuzz/$$t -max_total_time=$(SMOKE_SECONDS) -max_len=4096 -artifact_prefix=$$scratch/ \
	        $$scratch fuzz/corpus/$$t 2>$$scratch/log || { tail -40 $$scratch/log; exit 1; }; \
	    grep -E '^Done' $$scratch/log; rm -rf $$scratch; \
	done

# Longer runs (FUZZ_SECONDS each, default 600), keeping what they find in build/fuzz/corpus.
fuzz: fuzz-build
	@for t in $(FUZZ_TARGETS); do \
	    mkdir -p $(FUZZ_BUILD)/corpus/$$t; \
	    ASAN_OPTIONS=malloc_context_size=0 $(FUZZ_BUILD)/fuzz/$$t -max_total_time=$(FUZZ_SECONDS) -max_len=4096 -print_final_stats=1 \
	        -artifact_prefix=$(FUZZ_BUILD)/ $(FUZZ_BUILD)/corpus/$$t fuzz/corpus/$$t || exit 1; \
	done

# 10^5 and 10^6 contacts / generators through the command line, with time and peak memory,
# then the nearly degenerate families up to 4 x 10^8 letters of output (docs/benchmarks.md).
large-inputs: build
	bash tools/large_inputs.sh $(BUILD)/momentlab build/large
	bash tools/degenerate_table.sh $(BUILD)/momentlab build/degenerate

# Agreement with engines nobody here wrote (Siconos, Box2D, cddlib; docs/validation.md). `make
# test` runs the validators at the sizes of `validate`; both targets rewrite their table in
# docs/validation.md. validate-long: 5x the LCP pairs with enumeration up to 6 contacts, 20x
# the Box2D scenes, 20x the cones (about ten minutes).
validate: build
	bash tools/validation_table.sh standard $(BUILD)

validate-long: build
	bash tools/validation_table.sh long $(BUILD)

# Instructions (valgrind's callgrind) of a SceneQuestions set-up and six wrenches on the cradle and
# the tangent of 10^4 contacts, three ways of asking them (docs/benchmarks.md).
instructions: build
	@command -v valgrind >/dev/null || { SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	    $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq valgrind >/dev/null; }
	bash tools/instructions.sh $(BUILD) build/degenerate

# Every table of docs/benchmarks.md but the nearly degenerate scenes' (`make large-inputs`) and
# the instruction counts (`make instructions`).
bench: build
	$(BUILD)/bench/bench_cone
	$(BUILD)/bench/bench_contact
	$(BUILD)/bench/bench_python
	$(BUILD)/bench/bench_stand
	@mkdir -p build/degenerate; for n in 1000 10000 100000; do [ -f build/degenerate/tangent_$$n.json ] || /usr/bin/python3 tools/families.py build/degenerate tangent $$n; done
	GLIBC_TUNABLES=glibc.malloc.hugetlb=1:glibc.malloc.top_pad=268435456:glibc.malloc.trim_threshold=1073741824 \
	    $(BUILD)/bench/bench_io build/degenerate  # the command's malloc settings for big files (apps/momentlab/main.cpp)

clean:
	rm -rf build out python/momentlab.egg-info
