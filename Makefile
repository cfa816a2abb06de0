# corlab: the two set-up commands of the README are `make run` and `make test`.
# Both install the missing Debian packages (apt-get, as root), configure and build Release.
SHELL := /bin/bash
PRESET ?= $(if $(CI),ci,release)
BUILD_DIR := build
JOBS ?= $(shell nproc)
CTEST_ARGS ?=
REPORT_DIR ?= out/report
REPORT_PRESET ?= quick

DEBIAN_PACKAGES := build-essential cmake ninja-build pkg-config \
  libeigen3-dev libfmt-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev \
  libgtest-dev libgmock-dev libbenchmark-dev pybind11-dev python3-dev python3-numpy \
  python3-matplotlib python3-pytest libopenmpi-dev openmpi-bin libgmsh-dev \
  libgsl-dev libmuparser-dev
# DEM real-code checks (issue 11; `make dem-check`, also run by `make test`). apt install time
# measured on the dev machine: lammps 5 s (13.6 MB), liggghts 6 s, yade 42 s (118 MB, 868 MB disk).
DEBIAN_PACKAGES += lammps liggghts yade

.PHONY: deps configure build run test test-cpp test-python bench format clean dem-check install

deps:
	@missing=$$(for p in $(DEBIAN_PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null \
	  | grep -q "install ok installed" || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "corlab: installing missing Debian packages: $$missing"; \
	  if [ "$$(id -u)" -ne 0 ]; then echo "corlab: run as root (apt-get) or install: $$missing" >&2; exit 1; fi; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-get update -qq && apt-get install -y -qq --no-install-recommends $$missing; \
	fi

configure: deps
	cmake --preset $(PRESET) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The main job: the paper's pipeline end to end (studies, fits, report) with the quick preset.
run: build
	./$(BUILD_DIR)/bin/corlab reproduce --preset $(REPORT_PRESET) --out $(REPORT_DIR)

test: build test-cpp test-python

test-cpp:
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

test-python:
	PYTHONPATH=$(CURDIR)/$(BUILD_DIR)/python CORLAB_BIN=$(CURDIR)/$(BUILD_DIR)/bin/corlab \
	  /usr/bin/python3 -m pytest -q python/tests

# DEM exports checked by running Debian's LAMMPS and LIGGGHTS (ctest label dem; part of `make test`).
dem-check: build
	cd $(BUILD_DIR) && ctest --output-on-failure -L dem $(CTEST_ARGS)

# The DEM C library (libcorlab_dem, corlab_dem.h, CMake config, pkg-config) into PREFIX.
PREFIX ?= /usr/local
install: build
	cmake --install $(BUILD_DIR) --prefix $(PREFIX) --component dem

bench: build
	for b in $(BUILD_DIR)/bin/*_benchmark; do $$b; done

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf $(BUILD_DIR)
