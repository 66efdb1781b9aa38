# peloid — one top-level Makefile (STYLE.md 12).
#
#   make run     install dependencies, build, run scenes/quickstart.cfg, plot it and write its report
#   make check   install dependencies, build, run the test suite
#   make validate  the long physics validations (drag, diffusion, VACF), then the paper studies and
#                  validation/REPORT.md (make validate-physics: the validations alone, what CI runs)
#   make bench   kernel and whole-step benchmarks (bench/out/*.tsv)
#
# src/ + kernels/ build build/libpeloid.a, which bin/peloid, tests/ and bench/ link.

CC       ?= gcc
PYTHON   := /usr/bin/python3
PKGS     := hdf5 gsl hwloc libconfig jansson
# the commit, with "-dirty" when the sources that build peloid differ from it
# (summary.json's git_revision then does not claim a commit it was not built from)
GIT_REV  := $(shell r=$$(git rev-parse --short HEAD 2>/dev/null) || r=unknown; \
              if [ "$$r" != unknown ] && ! git diff --quiet HEAD -- src include kernels Makefile 2>/dev/null; \
              then r=$$r-dirty; fi; echo $$r)
OPTFLAGS ?= -O3 -march=native
WARN     := -Wall -Wextra -Wconversion -Wshadow -Wmissing-prototypes -Wstrict-prototypes -Werror
DEFS     ?=
BUILD    ?= build
# -ffp-contract=off: no fused multiply-adds the source does not write (GCC's
# ISO C mode already does this; clang fuses within an expression by
# default), so two code paths that the source makes bitwise equal (e.g. the
# potential coupling's pair-list and lookup force kernels) stay equal in
# every compiler build.
CFLAGS_ALL = -std=c11 $(OPTFLAGS) $(WARN) -fno-common -ffp-contract=off -fopenmp -D_GNU_SOURCE \
             -Iinclude -I$(BUILD)/gen -Isrc/io -Isrc/scene $(shell pkg-config --cflags $(PKGS) 2>/dev/null) $(DEFS)
LDLIBS_ALL = $(shell pkg-config --libs $(PKGS) 2>/dev/null) -lm -fopenmp
# src/ by layer (README "Layout"): core (the step, its stages and plan, the
# module table, whole-simulation checkpoints); the components fluid, colloid,
# coupling, observe; scene (input), mapping (units), io (HDF5, JSON and
# atomic-file helpers); app (run, calibrate, advise, sweep and study, and
# src/app/main.c, the command line, which is not in the library).
MAIN_SRC := src/app/main.c
LIB_SRC  := $(filter-out $(MAIN_SRC),$(wildcard src/*/*.c)) $(wildcard kernels/*.c)
LIB_OBJ  := $(patsubst %.c,$(BUILD)/%.o,$(LIB_SRC))
LIB      := $(BUILD)/libpeloid.a
BIN      := bin/peloid
# Tests by kind, one folder each (README "Tests"): tests/unit (make check and
# the sanitizer build), tests/physics (make check: physics runs too long for
# the sanitizers), tests/validation (make validate-physics), tests/cli and
# tests/fault (scripts on the command line), tests/support (their shared
# headers and helpers), tests/manual (by hand).  Every list below comes
# from these folders; a binary is $(BUILD)/tests/NAME whatever its kind.
UNIT_SRC := $(wildcard tests/unit/test_*.c)
PHYS_SRC := $(wildcard tests/physics/test_*.c)
VAL_SRC  := $(wildcard tests/validation/test_*.c)
TEST_SRC := $(UNIT_SRC) $(PHYS_SRC) $(VAL_SRC)
test_bins = $(patsubst %.c,$(BUILD)/tests/%,$(notdir $(1)))
TEST_BIN := $(call test_bins,$(TEST_SRC))
vpath test_%.c tests/unit tests/physics tests/validation
BENCH_SRC:= $(wildcard bench/*.c)
BENCH_BIN:= $(patsubst bench/%.c,$(BUILD)/bench/%,$(BENCH_SRC))

# Debian packages the build, the tests and the tools need (python3-mdanalysis,
# python3-ase and paraview: tests/cli/readers.sh opens the outputs with them;
# slurm-wlm: tests/cli/sweep_slurm.sh starts a one-node Slurm, as root).
DEB_PKGS := libgsl-dev libhwloc-dev librandom123-dev libhdf5-dev libconfig-dev libjansson-dev \
            libcriterion-dev pkg-config hwloc python3-numpy python3-h5py \
            python3-matplotlib python3-scipy python3-mdanalysis python3-ase paraview slurm-wlm
# ... and the build variants CI also checks (clang with its OpenMP runtime).
DEB_PKGS_VARIANTS := clang libomp-dev
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
PREFIX ?= /usr/local

.PHONY: all deps deps-variants install-debs run check check-build check-unit check-cli check-asan check-variants validate validate-physics bench clean keys \
        readme install
all: $(BIN)

# Installs only what is missing; a no-op on a machine that has everything.
deps:
	@$(MAKE) --no-print-directory install-debs PKGS_WANTED="$(DEB_PKGS)"
deps-variants:
	@$(MAKE) --no-print-directory install-debs PKGS_WANTED="$(DEB_PKGS_VARIANTS)"
install-debs:
	@missing=$$(for p in $(PKGS_WANTED); do dpkg -s $$p >/dev/null 2>&1 || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing Debian packages:" $$missing; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing >/dev/null; \
	fi

# Build information as a generated header, rewritten only when it changes:
# a new commit rebuilds the files that include it (summary.json, H5MD
# creator, benchmark banners), changed flags rebuild everything (flags.stamp).
BUILD_INFO = \#define PL_GIT_REV "$(GIT_REV)"\n\#define PL_CFLAGS "$(OPTFLAGS) $(DEFS)"\n\#define PL_TOOLS_DIR "$(CURDIR)/tools"\n\#define PL_CALIBRATION_DIR "$(CURDIR)/calibration"
$(BUILD)/gen/peloid_build.h: FORCE
	@mkdir -p $(dir $@)
	@printf '/* generated by the Makefile */\n$(BUILD_INFO)\n' > $@.new
	@if cmp -s $@.new $@; then rm -f $@.new; else mv $@.new $@; fi
$(BUILD)/flags.stamp: FORCE
	@mkdir -p $(dir $@)
	@echo '$(CC) $(CFLAGS_ALL) $(LDLIBS_ALL)' > $@.new
	@if cmp -s $@.new $@; then rm -f $@.new; else mv $@.new $@; fi
.PHONY: FORCE
FORCE:

$(BUILD)/%.o: %.c $(BUILD)/flags.stamp | deps $(BUILD)/gen/peloid_build.h
	@mkdir -p $(dir $@)
	@echo "  CC      $<"
	@$(CC) $(CFLAGS_ALL) -MMD -MP -c $< -o $@

# The colloid pair kernel computes energies only when asked: without errno
# the compiler may drop the unused logarithm of the van der Waals energy (no
# code reads errno after a math call); without trapping math it may turn the
# far-pair selects into SIMD blends (no code reads the floating-point
# exception flags).  Neither changes a computed value.
$(BUILD)/kernels/colloid_forces.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math
$(BUILD)/kernels/colloid_slow.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math
# The potential coupling's selection (kernels/coupling_select.c) takes the
# speed of each particle near a colloid (a square root of a sum of squares,
# never negative): without errno it vectorises; sqrt is correctly rounded
# either way.  Its WCA pair pass and its fused MD step (coupling_wca.c,
# coupling_potential.c) also compile to more vector code with the two flags
# (pl_coupling_wca_pair_block, the fused step's loop): the same values.
$(BUILD)/kernels/coupling_select.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math
$(BUILD)/kernels/coupling_order.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math
$(BUILD)/kernels/coupling_wca.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math
$(BUILD)/kernels/coupling_potential.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math
# The colloids' orientation update (kernels/colloid_integrate.h, in both the
# fused step of the MD region and the separate drift) normalises by a square root of a sum of
# squares in vector lanes: the same.
$(BUILD)/kernels/colloid_md_region.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math
$(BUILD)/kernels/colloid_integrate.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math
# The collision draws its random axes in vector lanes (a square root of
# 1 - s, s < 1, per cell): the same.
$(BUILD)/kernels/srd_collide.o: CFLAGS_ALL += -fno-math-errno -fno-trapping-math

$(LIB): $(LIB_OBJ)
	@rm -f $@
	@echo "  AR      $@"
	@ar rcs $@ $^

$(BIN): $(BUILD)/src/app/main.o $(LIB)
	@mkdir -p bin
	@echo "  LD      $@"
	@$(CC) $(CFLAGS_ALL) -o $@ $^ $(LDLIBS_ALL)

# The CLI of another build (the sanitizer build: build-asan/bin/peloid).
$(BUILD)/bin/peloid: $(BUILD)/src/app/main.o $(LIB)
	@mkdir -p $(dir $@)
	@echo "  LD      $@"
	@$(CC) $(CFLAGS_ALL) -o $@ $^ $(LDLIBS_ALL)

$(BUILD)/tests/test_%: test_%.c $(LIB) $(BUILD)/flags.stamp | deps $(BUILD)/gen/peloid_build.h
	@mkdir -p $(dir $@)
	@echo "  TEST    $@"
	@$(CC) $(CFLAGS_ALL) -Itests/support -MMD -MP -o $@ $< $(LIB) $(LDLIBS_ALL) -lcriterion -lgsl -lgslcblas

$(BUILD)/bench/%: bench/%.c $(LIB) $(BUILD)/flags.stamp | deps $(BUILD)/gen/peloid_build.h
	@mkdir -p $(dir $@)
	@echo "  BENCH   $@"
	@$(CC) $(CFLAGS_ALL) -MMD -MP -o $@ $< $(LIB) $(LDLIBS_ALL)

run: $(BIN)
	./$(BIN) run scenes/quickstart.cfg --force
	$(PYTHON) tools/plot_sediment.py out/quickstart
	./$(BIN) report out/quickstart

# The suite: Criterion unit + physics tests, then CLI behaviour, then a
# sanitizer build of the fast unit tests.
# Builds run on every core first (the optimised and the sanitizer build),
# then the suites one after the other.
NPROC := $(shell nproc 2>/dev/null || echo 1)
check: | deps
	@$(MAKE) --no-print-directory -j$(NPROC) check-build
	@$(MAKE) --no-print-directory -j$(NPROC) --output-sync=target check-suites
	@echo "make check: all suites passed"
check-build: $(CHECK_BIN) $(BIN)
	@$(MAKE) --no-print-directory $(ASAN_MAKE) $(patsubst %,build-asan/tests/%,$(ASAN_TESTS)) build-asan/bin/peloid

# The long physics validations (each several minutes on 2 cores) run in
# `make validate-physics`; `make validate` runs them, then the paper studies
# (make studies, ~40 min on 2 cores) and regenerates validation/REPORT.md;
# `make check` runs everything else (tests/physics/test_mpc_viscosity short; here in full, MPC_VISC_FULL=1).
# CI runs check and validate-physics (the
# studies would take its total past 60 min).
VALIDATE_BIN := $(call test_bins,$(VAL_SRC))
CHECK_BIN := $(call test_bins,$(UNIT_SRC) $(PHYS_SRC))

check-unit: $(patsubst %,check-run/%,$(CHECK_BIN)) # the recipes of make check's lanes, one after another

validate-physics: $(VALIDATE_BIN) $(BUILD)/tests/test_mpc_viscosity $(BIN)
	@set -e; for t in $(VALIDATE_BIN); do echo "== $$t"; $$t --jobs 1; done
	@echo "== test_mpc_viscosity (full: 3 % at two parameter sets)"; MPC_VISC_FULL=1 $(BUILD)/tests/test_mpc_viscosity --jobs 1
	@bash tests/cli/stress.sh ./$(BIN) 80000
	@set -e; for t in $(wildcard tests/validation/*.sh); do bash $$t ./$(BIN); done
	@echo "make validate-physics: all suites passed"
validate: validate-physics
	@$(MAKE) --no-print-directory studies validation-report
	@echo "make validate: all suites passed, validation/REPORT.md regenerated"

# the command-line suites and the fault scripts short enough for make check
# (tests/fault/fault_trials.sh, minutes of signals at random moments, runs in
# make fault-trials only)
CLI_SUITES := $(wildcard tests/cli/*.sh) $(filter-out tests/fault/fault_trials.sh,$(wildcard tests/fault/*.sh))
check-cli: $(patsubst %,check-run/%,$(CLI_SUITES))

# The fault trials in one command (CI runs it): signals at random moments
# then resume in place (tests/fault/fault_trials.sh), concurrent runs and sweeps
# under signals (tests/fault/sweep_signals.sh), a full disk (tests/fault/full_disk.sh,
# a tmpfs as root) and OpenMP settings (tests/fault/omp_env.sh).
.PHONY: fault-trials
fault-trials: $(BIN)
	@set -e; for t in $(wildcard tests/fault/*.sh); do s=$$(date +%s); bash $$t ./$(BIN); \
	  echo "   ($$t: $$(( $$(date +%s) - s )) s)"; done
	@echo "make fault-trials: all trials passed"

# Address + undefined-behaviour sanitizers on the quick suites (PL_QUICK=1
# shrinks the physics runs; the sanitizers slow code ~3-10x), and the
# sanitizer CLI on the adversarial scene set (tests/bad_scenes).
ASAN_TESTS := $(basename $(notdir $(UNIT_SRC))) # tests/unit, every one
ASAN_MAKE = BUILD=build-asan \
  OPTFLAGS="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
check-asan: | deps
	@$(MAKE) --no-print-directory $(ASAN_MAKE) $(patsubst %,build-asan/tests/%,$(ASAN_TESTS)) build-asan/bin/peloid
	@$(MAKE) --no-print-directory $(patsubst %,check-run-asan/%,$(ASAN_TESTS)) check-run-asan-bad-scenes

# make check runs its suites $(NPROC) at a time (most use one core), each
# suite's output printed whole when it ends (--output-sync); the longest
# first, so that the lanes end together.  check-unit, check-cli and
# check-asan run the same recipes one after the other.
SLOW_SUITES := tests/cli/studies_reduced.sh tests/cli/observers.sh tests/cli/cli.sh tests/cli/sweep.sh \
               tests/cli/stress.sh tests/cli/regression.sh
CHECK_RUNS := $(patsubst %,check-run/%,$(SLOW_SUITES) $(filter-out $(SLOW_SUITES),$(CLI_SUITES)) $(CHECK_BIN)) \
              $(patsubst %,check-run-asan/%,$(ASAN_TESTS)) check-run-asan-bad-scenes
.PHONY: check-suites check-run-asan-bad-scenes
check-suites: $(CHECK_RUNS)
check-run/%.sh: $(BIN)
	@set -e; s=$$(date +%s); bash $*.sh ./$(BIN); echo "   ($*.sh: $$(( $$(date +%s) - s )) s)"
check-run/$(BUILD)/tests/%: $(BUILD)/tests/%
	@set -e; echo "== $<"; s=$$(date +%s); $< --jobs 1; echo "   ($<: $$(( $$(date +%s) - s )) s)"
check-run-asan/%:
	@set -e; s=$$(date +%s); echo "== asan $*"; ASAN_OPTIONS=detect_leaks=1 PL_QUICK=1 build-asan/tests/$* --jobs 1; \
	  echo "   (asan $*: $$(( $$(date +%s) - s )) s)"
check-run-asan-bad-scenes:
	@echo "== asan bin/peloid on tests/bad_scenes"
	@ASAN_OPTIONS=detect_leaks=1 bash tests/support/bad_scenes.sh build-asan/bin/peloid

# The studies of issue 16 (studies/*.cfg, each a `peloid sweep`; resumable:
# a finished point is not run again) and validation/REPORT.md from their
# outputs in out/studies/.
.PHONY: studies validation-report validation-verdicts validation-update validation-notes
STUDIES := studies/hecht_fig9_kappa.cfg studies/hecht_fig9_kappa_replica.cfg studies/hecht_fig9_kappa_1s.cfg \
           studies/hecht_fig9_bonds.cfg studies/hecht_fig5_rdf.cfg studies/hecht_fig4_rz.cfg studies/hecht_fig14_msd.cfg \
           studies/pl_fig6_drag.cfg studies/accuracy_viscosity.cfg \
           studies/hecht_fig9_diagram.cfg studies/hecht_fig9_phi.cfg studies/accuracy_fluid_diffusion.cfg \
           studies/pl_fig10_vacf.cfg studies/pl_fig4_rdf.cfg studies/pl_fig4_rdf_bd_dt.cfg \
           studies/pl_fig11_dphi.cfg studies/pl_fig11_dphi_solvent.cfg studies/accuracy_drag_substeps.cfg \
           studies/hecht_fig9_lub.cfg studies/hecht_fig9_lub_3s.cfg studies/hecht_fig9_bd.cfg studies/pl_fig11_dphi_bd.cfg \
           studies/pl_fig4_rdf_long.cfg studies/pl_fig4_rdf_bd_long.cfg studies/pl_fig10_vacf_l64.cfg
# A sweep exits 1 when some of its points failed (a guard trip, recorded with its message: the Fig. 9
# diagram's points without a DLVO barrier, the drag guide's 1 MD substep); the report shows them, so that
# is not an error here; any other failure (bad input: 2) stops make studies.
studies: $(BIN)
	@set -e; for s in $(STUDIES); do ./$(BIN) sweep $$s || [ $$? -eq 1 ]; done
validation-report:
	$(PYTHON) tools/validation_report.py out/studies validation/REPORT.md
# Only the section "Verdicts of the disagreement rows" (tools/validation/verdicts.py), the rest of the report kept.
validation-verdicts:
	$(PYTHON) tools/validation_report.py --verdicts-only out/studies validation/REPORT.md
# Only the rows of the named entries (ENTRIES=hecht_fig9_kappa,hecht_fig4_rz: their sweeps rerun into
# out/studies), the notes and the verdicts; the other rows kept.
validation-update:
	$(PYTHON) tools/validation_report.py --update $(ENTRIES) out/studies validation/REPORT.md
# Only the notes (NOTES in tools/validation_report.py), every row kept.
validation-notes:
	$(PYTHON) tools/validation_report.py --notes-only out/studies validation/REPORT.md

bench: $(BENCH_BIN)
	@mkdir -p bench/out
	@set -e; for b in $(BENCH_BIN); do $$b; done

# The shipped calibrations (calibration/*.json, src/app/calibrate.c): the
# colloid diffusion of coupling I/II at the resolution of every shipped
# physical scene and study base, measured afresh.
.PHONY: calibrations
calibrations: $(BIN)
	rm -f calibration/calibration-*.json
	@set -e; for s in scenes/*.cfg studies/*_base.cfg tests/calibration/*.cfg; do \
	  PELOID_CACHE=$(CURDIR)/calibration PELOID_NO_SHIPPED_CALIBRATION=1 ./$(BIN) check $$s > /dev/null; done
	rm -f calibration/*.lock

keys: $(BIN)
	./$(BIN) keys

# README's scene-key reference is generated from the schema.
readme: $(BIN)
	$(PYTHON) tools/readme_keys.py ./$(BIN) README.md

# Build variants: clang (its own warnings, its OpenMP runtime) and single
# precision storage (-DPL_SINGLE), each built -Werror clean; each runs the
# thread-count determinism suite and a short quickstart.  The precision-bound
# unit tests (conservation to 1e-14) are for the double build only.
VARIANT_TESTS := test_determinism test_scene test_sort
check-variants: | deps deps-variants
	@set -e; for v in "clang:CC=clang" "single:DEFS=-DPL_SINGLE"; do \
	  name=$${v%%:*}; arg=$${v#*:}; \
	  echo "== build variant $$name ($$arg)"; \
	  $(MAKE) --no-print-directory BUILD=build-$$name "$$arg" build-$$name/bin/peloid \
	    $(patsubst %,build-$$name/tests/%,$(VARIANT_TESTS)); \
	  for t in $(VARIANT_TESTS); do PL_QUICK=1 build-$$name/tests/$$t --jobs 1; done; \
	  rm -rf build-$$name/out; build-$$name/bin/peloid run scenes/quickstart.cfg --steps 20 \
	    --out build-$$name/out 2>/dev/null; \
	  echo "  ok   $$name: quickstart 20 steps"; \
	done

# make install [PREFIX=/usr/local] [DESTDIR=...]: the CLI, libpeloid.a, the
# public headers and peloid.pc (pkg-config --cflags --libs peloid).
install: $(BIN) $(LIB)
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/include/peloid
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/
	install -m 644 $(LIB) $(DESTDIR)$(PREFIX)/lib/
	install -m 644 include/peloid/*.h $(DESTDIR)$(PREFIX)/include/peloid/
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(GIT_REV)|' tools/peloid.pc.in \
	  > $(DESTDIR)$(PREFIX)/lib/pkgconfig/peloid.pc

clean:
	rm -rf build build-asan build-clang build-single bin

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
