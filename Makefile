# corlab: the two set-up commands of the README are `make run` and `make test`.
# Both install the missing Debian packages (apt-get, as root), configure and build Release.
# SPDX-License-Identifier: BSD-3-Clause
SHELL := /bin/bash
PRESET ?= $(if $(CI),ci,release)
BUILD_DIR := build
JOBS ?= $(shell nproc)
CTEST_ARGS ?=
REPORT_DIR ?= out/report
REPORT_PRESET ?= paper

DEBIAN_PACKAGES := build-essential cmake ninja-build pkg-config \
  libeigen3-dev libfmt-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev \
  libgtest-dev libgmock-dev libbenchmark-dev pybind11-dev python3-dev python3-numpy \
  python3-matplotlib python3-scipy python3-pytest libopenmpi-dev openmpi-bin libgmsh-dev \
  libgsl-dev libmuparser-dev python3-mypy \
  clang-tidy python3-flake8 help2man
# The e(v) explorer (docs/user/explorer.md) needs only these: emscripten compiles corlab's C++ to
# WebAssembly, the header-only libraries it includes, python3-plotly ships plotly.js, dpkg-dev
# unpacks GSL's Debian source package (for src/dem's DEM export). No DEM code, no browser.
EXPLORER_DEBIAN_PACKAGES := emscripten python3-plotly libfmt-dev libtomlplusplus-dev \
  nlohmann-json3-dev dpkg-dev cmake ninja-build
# Only the tests need these: the DEM codes the DEM exports are checked with (issue 11; apt install
# time measured on the dev machine: lammps 5 s (13.6 MB), liggghts 6 s, yade 42 s (118 MB, 868 MB
# disk)), python3-lammps and python3-scipy (the LAMMPS export's fix python/invoke hook),
# liblammps-dev (LAMMPS's headers and CMake package: corlab-lammps, the compiled e(v) route of
# lammps_compiled.in, is built when configure finds it), headless
# chromium driven by selenium (the explorer's and the report's browser tests), lintian (the .deb).
# `make test` installs them, `make run` does not.
TEST_DEBIAN_PACKAGES := lammps liggghts yade python3-lammps python3-scipy liblammps-dev \
  chromium chromium-driver python3-selenium lintian $(EXPLORER_DEBIAN_PACKAGES)

.PHONY: deps deps-test configure build run test test-cpp test-python test-asan lint lint-cpp lint-python \
  bench format clean dem-check install uninstall deb golden-rebaseline explorer
.PHONY: build-all first-answer lint-spdx deps-explorer

# Installs the missing packages of $(1) with apt-get (as root).
define apt_install
	@missing=$$(for p in $(1); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null \
	  | grep -q "install ok installed" || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "corlab: installing missing Debian packages: $$missing"; \
	  if [ "$$(id -u)" -ne 0 ]; then echo "corlab: run as root (apt-get) or install: $$missing" >&2; exit 1; fi; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-get update -qq && apt-get install -y -qq --no-install-recommends $$missing; \
	fi
endef

deps:
	$(call apt_install,$(DEBIAN_PACKAGES))

deps-test:
	$(call apt_install,$(TEST_DEBIAN_PACKAGES))

deps-explorer:
	$(call apt_install,$(EXPLORER_DEBIAN_PACKAGES))

configure: deps
	cmake --preset $(PRESET) -DCMAKE_BUILD_TYPE=Release

# `make build`: the tool only (target `tool`: the CLI, libcorlab, libcorlab_dem, the Python module);
# `make build-all`: also the tests, fuzz targets, benchmarks and examples (what `make test` needs).
build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target tool

build-all: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The main job: a first answer in a second (corlab2026's e(v), alumina on aluminium), then the
# paper's pipeline end to end (studies, fits, report) at the paper's resolution.
run: build first-answer
	./$(BUILD_DIR)/bin/corlab reproduce --preset $(REPORT_PRESET) --out $(REPORT_DIR)

FIRST_ANSWER := predict --model corlab2026 --sphere alumina_ma2023 --substrate aluminium_ma2023 \
  --velocity 0.1:10:6 --spacing log
first-answer: build
	@echo "corlab: first answer (e at 0.1-10 m/s): corlab $(FIRST_ANSWER)"
	@./$(BUILD_DIR)/bin/corlab $(FIRST_ANSWER)

test: deps-test build-all explorer test-cpp test-python lint test-asan

test-cpp:
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

# CORLAB_EXPLORER: the page the browser tests open; CORLAB_ARTEFACTS: where they keep screenshots.
test-python:
	PYTHONPATH=$(CURDIR)/$(BUILD_DIR)/python CORLAB_BIN=$(CURDIR)/$(BUILD_DIR)/bin/corlab \
	  CORLAB_EXPLORER=$(CURDIR)/$(EXPLORER_DIR)/explorer.html \
	  CORLAB_ARTEFACTS=$(CURDIR)/$(BUILD_DIR)/browser \
	  /usr/bin/python3 -m pytest -q python/tests

# The e(v) explorer: corlab's materials, restitution and dem sources compiled to WebAssembly by
# Debian's emscripten and inlined with plotly.js into one offline page, $(EXPLORER_DIR)/explorer.html
# (docs/user/explorer.md). It needs only EXPLORER_DEBIAN_PACKAGES (deps-explorer) and GSL's
# source: src/dem (the page's DEM export) calls GSL's ODE, root and minimiser routines, and Debian
# ships GSL only as x86 libraries, so its source package is fetched once with apt-get source
# through a private source list (the system's apt configuration is untouched) and the parts
# src/dem calls are compiled to WebAssembly (explorer/GslWasm.cmake). The browser tests' chromium
# comes with deps-test. NODE_PATH: emscripten's JavaScript tools use Debian's node modules.
EXPLORER_DIR := $(BUILD_DIR)/explorer
GSL_SOURCE := $(BUILD_DIR)/gsl-source
EMSCRIPTEN_ENV := NODE_PATH=/usr/share/nodejs
explorer: deps-explorer $(GSL_SOURCE)/gsl/configure
	$(EMSCRIPTEN_ENV) emcmake cmake -S explorer -B $(EXPLORER_DIR) -G Ninja \
	  -DCORLAB_GSL_SOURCE_DIR=$(CURDIR)/$(GSL_SOURCE)/gsl
	$(EMSCRIPTEN_ENV) cmake --build $(EXPLORER_DIR) -j $(JOBS)
	@echo "corlab: the explorer is $(EXPLORER_DIR)/explorer.html (open it in a browser)"

$(GSL_SOURCE)/gsl/configure:
	rm -rf $(GSL_SOURCE) && mkdir -p $(GSL_SOURCE)/lists/partial
	. /etc/os-release && echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg]" \
	  "http://deb.debian.org/debian $$VERSION_CODENAME main" > $(GSL_SOURCE)/sources.list
	cd $(GSL_SOURCE) && apt_private="-o Dir::Etc::SourceList=$$PWD/sources.list \
	  -o Dir::Etc::SourceParts=/dev/null -o Dir::State::Lists=$$PWD/lists" && \
	  apt-get -qq $$apt_private update && apt-get -qq $$apt_private source gsl && \
	  mv $$(find . -maxdepth 1 -type d -name 'gsl-*') gsl

# Static analysis: clang-tidy (.clang-tidy; scripts/lint/clang_tidy.sh lists what it leaves out)
# and flake8 (.flake8) on the Python sources. Both fail on any finding.
lint: lint-spdx lint-python lint-cpp

lint-cpp: build-all
	scripts/lint/clang_tidy.sh $(BUILD_DIR) $(JOBS)

lint-python:
	/usr/bin/python3 -m flake8 python scripts tests explorer

# Every source file carries `SPDX-License-Identifier: BSD-3-Clause` (LICENSE); `--fix` adds it.
lint-spdx:
	/usr/bin/python3 scripts/lint/spdx_headers.py --check

# DEM exports checked by running Debian's LAMMPS and LIGGGHTS (ctest label dem; part of `make test`).
dem-check: deps-test build-all
	cd $(BUILD_DIR) && ctest --output-on-failure -L dem $(CTEST_ARGS)

# Everything into PREFIX (default /usr/local; docs/user/install.md): the corlab program, the C++
# library libcorlab and the DEM C library libcorlab_dem with their headers, find_package(corlab)
# and pkg-config files, the data (share/corlab) and the Python package, where Debian's
# /usr/bin/python3 finds it. ldconfig (as root) makes the new libraries known to the loader.
# `make uninstall` (same PREFIX) removes exactly that (the files, and the folders the install
# created when they are empty) and leaves PREFIX as it was (scripts/install_prefix.sh).
PREFIX ?= /usr/local
install: build
	scripts/install_prefix.sh install $(BUILD_DIR) $(PREFIX)

uninstall:
	scripts/install_prefix.sh uninstall $(BUILD_DIR) $(PREFIX)

# A Debian package of the same (prefix /usr) with CPack: build/package/corlab_<version>_<arch>.deb.
deb: build
	cd $(BUILD_DIR) && cpack -G DEB

# AddressSanitizer + UndefinedBehaviorSanitizer (preset asan, build dir build-asan): the unit
# tests, the fuzz targets (fewer mutants) and the CLI input reproducers, then the verification
# cases that take < 2 s in a release build. Any sanitizer report fails the test. fuzz_gmsh is left
# out here (gmsh itself is not instrumented and its fork probe times out under ASan; the release
# build runs it).
ASAN_FAST_VERIFICATION := ^(Velocities/HertzElastic.MatchesHertz/1|PaperCase[.](SeparatesWithThePaperRestitution|EnergyBalanceHoldsThroughout|HourglassEnergyIsSmall|PenaltyPenetrationIsSmall))$$
test-asan: deps
	cmake --preset asan
	cmake --build build-asan -j $(JOBS)
	cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --output-on-failure -j $(JOBS) -L 'unit|fuzz' -E '^fuzz_gmsh$$' && \
	  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --output-on-failure --no-tests=error -j $(JOBS) -R '$(ASAN_FAST_VERIFICATION)|^regression_input_cli$$'

# The golden tier (docs/dev/testing.md): rerun its cases, print old and new side by side, rewrite
# tests/golden/golden.json.
golden-rebaseline: build-all
	./$(BUILD_DIR)/tests/golden_test --rebaseline

bench: build-all
	for b in $(BUILD_DIR)/bin/*_benchmark; do $$b; done

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf $(BUILD_DIR) build-asan
