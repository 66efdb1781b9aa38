# peloid — one top-level Makefile (STYLE.md 12).
#
#   make run     install dependencies, build, run scenes/quickstart.cfg and plot it
#   make check   install dependencies, build, run the test suite
#   make validate  the long physics validations (drag, diffusion, VACF)
#   make bench   kernel and whole-step benchmarks (bench/out/*.tsv)
#
# src/ + kernels/ build build/libpeloid.a, which bin/peloid, tests/ and bench/ link.

CC       ?= gcc
PYTHON   := /usr/bin/python3
PKGS     := hdf5 gsl hwloc libconfig jansson
GIT_REV  := $(shell git rev-parse --short HEAD 2>/dev/null || echo unknown)
OPTFLAGS ?= -O3 -march=native
WARN     := -Wall -Wextra -Wconversion -Wshadow -Werror
DEFS     ?=
CFLAGS_ALL = -std=c11 $(OPTFLAGS) $(WARN) -fno-common -fopenmp -D_GNU_SOURCE \
             -Iinclude $(shell pkg-config --cflags $(PKGS) 2>/dev/null) $(DEFS) \
             -DPL_GIT_REV='"$(GIT_REV)"' -DPL_CFLAGS='"$(OPTFLAGS) $(DEFS)"'
LDLIBS_ALL = $(shell pkg-config --libs $(PKGS) 2>/dev/null) -lm -fopenmp

BUILD    ?= build
LIB_SRC  := $(filter-out src/main.c,$(wildcard src/*.c)) $(wildcard kernels/*.c)
LIB_OBJ  := $(patsubst %.c,$(BUILD)/%.o,$(LIB_SRC))
LIB      := $(BUILD)/libpeloid.a
BIN      := bin/peloid
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
BENCH_SRC:= $(wildcard bench/*.c)
BENCH_BIN:= $(patsubst bench/%.c,$(BUILD)/bench/%,$(BENCH_SRC))

# Debian packages the build, the tests and the tools need (python3-mdanalysis,
# python3-ase and paraview: tests/readers.sh opens the outputs with them).
DEB_PKGS := libgsl-dev libhwloc-dev librandom123-dev libhdf5-dev libconfig-dev libjansson-dev \
            libcriterion-dev pkg-config hwloc python3-numpy python3-h5py \
            python3-matplotlib python3-scipy python3-mdanalysis python3-ase paraview
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps run check check-unit check-cli check-asan validate bench clean keys readme
all: $(BIN)

# Installs only what is missing; a no-op on a machine that has everything.
deps:
	@missing=$$(for p in $(DEB_PKGS); do dpkg -s $$p >/dev/null 2>&1 || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing Debian packages:" $$missing; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing >/dev/null; \
	fi

$(BUILD)/%.o: %.c | deps
	@mkdir -p $(dir $@)
	@echo "  CC      $<"
	@$(CC) $(CFLAGS_ALL) -MMD -MP -c $< -o $@

# The colloid pair kernel computes energies only when asked: without errno
# the compiler may drop the unused logarithm of the van der Waals energy (no
# code reads errno after a math call); without trapping math it may turn the
# far-pair selects into SIMD blends (no code reads the floating-point
# exception flags).  Neither changes a computed value.
$(BUILD)/kernels/colloid_forces.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math

$(LIB): $(LIB_OBJ)
	@rm -f $@
	@echo "  AR      $@"
	@ar rcs $@ $^

$(BIN): $(BUILD)/src/main.o $(LIB)
	@mkdir -p bin
	@echo "  LD      $@"
	@$(CC) $(CFLAGS_ALL) -o $@ $^ $(LDLIBS_ALL)

# The CLI of another build (the sanitizer build: build-asan/bin/peloid).
$(BUILD)/bin/peloid: $(BUILD)/src/main.o $(LIB)
	@mkdir -p $(dir $@)
	@echo "  LD      $@"
	@$(CC) $(CFLAGS_ALL) -o $@ $^ $(LDLIBS_ALL)

$(BUILD)/tests/%: tests/%.c $(LIB) | deps
	@mkdir -p $(dir $@)
	@echo "  TEST    $@"
	@$(CC) $(CFLAGS_ALL) -MMD -MP -o $@ $< $(LIB) $(LDLIBS_ALL) -lcriterion -lgsl -lgslcblas

$(BUILD)/bench/%: bench/%.c $(LIB) | deps
	@mkdir -p $(dir $@)
	@echo "  BENCH   $@"
	@$(CC) $(CFLAGS_ALL) -o $@ $< $(LIB) $(LDLIBS_ALL)

run: $(BIN)
	./$(BIN) run scenes/quickstart.cfg --force
	$(PYTHON) tools/plot_sediment.py out/quickstart

# The suite: Criterion unit + physics tests, then CLI behaviour, then a
# sanitizer build of the fast unit tests.
check: check-unit check-cli check-asan
	@echo "make check: all suites passed"

# The long physics validations (each several minutes on 2 cores) run in
# `make validate`; `make check` runs everything else.  CI runs both.
VALIDATE_TESTS := test_coupling_drag test_coupling_vacf
VALIDATE_BIN := $(patsubst %,$(BUILD)/tests/%,$(VALIDATE_TESTS))
CHECK_BIN := $(filter-out $(VALIDATE_BIN),$(TEST_BIN))

check-unit: $(CHECK_BIN)
	@set -e; for t in $(CHECK_BIN); do echo "== $$t"; $$t --jobs 1; done

validate: $(VALIDATE_BIN)
	@set -e; for t in $(VALIDATE_BIN); do echo "== $$t"; $$t --jobs 1; done
	@echo "make validate: all suites passed"

check-cli: $(BIN)
	@bash tests/cli.sh ./$(BIN)
	@bash tests/restart_guard.sh ./$(BIN)
	@bash tests/full_disk.sh ./$(BIN)
	@bash tests/readers.sh ./$(BIN)

# Address + undefined-behaviour sanitizers on the quick suites (PL_QUICK=1
# shrinks the physics runs; the sanitizers slow code ~3-10x), and the
# sanitizer CLI on the adversarial scene set (tests/bad_scenes).
ASAN_TESTS := test_scene test_collide test_sort test_determinism test_colloid_forces \
              test_colloid_guards test_colloid_md test_colloid_restart test_capillary \
              test_coupling_restart test_coupling_system test_fluid_guard test_progress
check-asan: | deps
	@$(MAKE) --no-print-directory BUILD=build-asan \
	  OPTFLAGS="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" \
	  $(patsubst %,build-asan/tests/%,$(ASAN_TESTS)) build-asan/bin/peloid
	@set -e; for t in $(ASAN_TESTS); do \
	  echo "== asan $$t"; ASAN_OPTIONS=detect_leaks=1 PL_QUICK=1 build-asan/tests/$$t --jobs 1; done
	@echo "== asan bin/peloid on tests/bad_scenes"
	@ASAN_OPTIONS=detect_leaks=1 bash tests/bad_scenes.sh build-asan/bin/peloid

bench: $(BENCH_BIN)
	@mkdir -p bench/out
	@set -e; for b in $(BENCH_BIN); do $$b; done

keys: $(BIN)
	./$(BIN) keys

# README's scene-key reference is generated from the schema.
readme: $(BIN)
	$(PYTHON) tools/readme_keys.py ./$(BIN) README.md

clean:
	rm -rf build build-asan bin

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
