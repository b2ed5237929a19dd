# photon -- a reference implementation of photon mapping in C99. See README.md.
#
#   make            build ./photon with the system cc
#   make run        build, then render the specular Cornell box with photon maps (--mode 1994)
#   make test       build and run every test; ends with "N passed, N failed". Needs nothing
#                   outside the repository (outside data it reads is in tests/data/)
#   make test-spd SPD=DIR
#                   the tests against all 22 files of Haines' Standard Procedural Databases,
#                   read from the folder DIR (too large to keep here: tests/data/README.md)
#   make check      the tests built by gcc and clang with -Werror, by tcc, and under
#                   AddressSanitizer + UndefinedBehaviorSanitizer
#   make bench      benchmark figures (ONLY=rays|knn|...|tiles runs one workload); SPD=DIR
#                   adds the workloads on SPD files, which are skipped without it
#   make figures    re-measure the figures README.md states and write them into it (long;
#                   ONLY=presets|bench|tts for one part; bench is the tte workload's
#                   table, tts time to a stated error, TTS_LIMIT=S each render's limit);
#                   ONLY=rays SPD=DIR writes bench-embree's table into tests/bench/README.md,
#                   ONLY=pbrt PBRT=PATH bench-pbrt's, ONLY=cycles bench-cycles'
#   make reference  render the converged references of reference/suite.txt and write
#                   reference/suite.md (hours; says how long first; ONLY=NAME for one)
#   make consistency
#                   every photon mode on every shipped scene against its reference, the
#                   table written into reference/suite.md, and 2008 and 2009 at
#                   --target-error 0.02 (hours; says how long first; ONLY=NAME for some
#                   scenes, MODES="1996 2009", QUALITY=reference, KINDS=target)
#   make calibration
#                   whether each mode's stated error (--error) holds on every shipped scene,
#                   at its defaults and at --target-error 0.02, against the references: the
#                   table written into reference/suite.md (hours; ONLY=NAME for some scenes)
#   make bench-embree SPD=DIR
#                   the rays workload cast through Embree 3 beside photon in one run: both
#                   throughputs, their ratio, both checksums (tests/bench/embree/bench_embree.c;
#                   needs libembree-dev, which the product never links; development)
#   make bench-pbrt PBRT=PATH
#                   --mode 2009 against pbrt-v4's SPPM (PATH its pbrt program), one thread,
#                   equal CPU seconds, on both Cornell boxes: each one's seconds, relmse and
#                   worst block, and the ratio of the errors (scripts/bench_pbrt.sh; about 6
#                   minutes of CPU; ONLY=cornell or cornell-specular; development)
#   make bench-cycles
#                   --mode pt against Blender's Cycles (blender 3.4+, as for crosscheck),
#                   one thread, equal CPU seconds (Cycles' render's, then pt's
#                   --time-limit), on both Cornell boxes at CYCLES_SPP Cycles samples
#                   (default "16 64 256"): each one's seconds, relmse and worst block, and
#                   the ratio of the errors (scripts/bench_cycles.sh; about 4 minutes of
#                   CPU; ONLY=cornell or cornell-specular; BLENDER=PATH; development)
#   make fuzz       libFuzzer targets for every reader (scene, NFF, OBJ, PFM, OpenEXR, CSV, tile
#                   record, work file), the option parser and deflate's round trip through
#                   inflate, built with clang (development)
#   make crosscheck our references against Blender's Cycles, where blender (3.4+) is
#                   installed: each scene exported, rendered, compared (ONLY=NAME for
#                   some; CROSSCHECK_SPP, default 4096: about 35 minutes for all;
#                   scripts/crosscheck.sh; development)
#   make install    photon in $(DESTDIR)$(PREFIX)/bin, its manual page photon.1 (written by
#                   photon --manual: --help all's text and the page's own sections) in
#                   share/man/man1, the shipped scenes in share/photon; PREFIX defaults to
#                   /usr/local. make uninstall removes exactly those files (and the
#                   share/photon folders, once empty)
#   make clean
#
# BUILD names the object directory, so several compilers can build side by side.

CC ?= cc
BUILD ?= build
BIN ?= photon
OPT ?= -O2
# No FMA contraction: gcc, clang and tcc must round every operation alike (README).
FPFLAGS ?= -ffp-contract=off
# gcc 12's SLP vectoriser drops double -> float -> double roundings at -O2 (three adjacent
# (float) casts stored into doubles come out unrounded), so gcc builds turn it off.
ifneq ($(shell $(CC) --version 2>/dev/null | grep -c 'Free Software Foundation'),0)
FPFLAGS += -fno-tree-slp-vectorize
endif
WARN ?= -Wall -Wextra -pedantic
EXTRA ?=
CFLAGS = -std=c99 $(OPT) $(FPFLAGS) $(WARN) $(EXTRA)
LDLIBS = -lm

SRC := $(sort $(wildcard src/*/*.c))
HEADERS := $(wildcard src/*/*.h tests/*.h tests/bench/*.h)
LIB_OBJ := $(SRC:%.c=$(BUILD)/%.o)
MAIN_OBJ := $(BUILD)/src/main.o
# The tests also check the tte workload's fit of pt's error (tests/bench/tte_fit.c).
TEST_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(sort $(wildcard tests/*.c)) tests/bench/tte_fit.c)
BENCH_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(sort $(wildcard tests/bench/*.c)))

.PHONY: all run test test-spd check bench bench-embree bench-pbrt bench-cycles figures \
        reference consistency calibration fuzz crosscheck install uninstall clean

# test-spd refuses at once, before building anything, when it has no folder of SPD files.
ifneq ($(filter test-spd,$(MAKECMDGOALS)),)
ifeq ($(SPD),)
$(error make test-spd needs SPD=DIR, a folder of the SPD .nff files (balls-s4.nff, ...))
endif
ifeq ($(wildcard $(SPD)/*.nff),)
$(error make test-spd: SPD=$(SPD) is not a folder of .nff files)
endif
endif

all: $(BIN)

$(BUILD)/%.o: %.c $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(BIN): $(MAIN_OBJ) $(LIB_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/run_tests: $(TEST_OBJ) $(LIB_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/bench: $(BENCH_OBJ) $(LIB_OBJ)
	$(CC) $(CFLAGS) -o $@ $^ $(LDLIBS)

# 1994's photon maps with fewer light rays, gather rays and samples than its defaults: the
# caustic under the glass ball and the walls' colour on the floor and ceiling in about 20 CPU s.
RUN_OPTIONS = --mode 1994 --photons 1000000 --gather-rays 128 --cache-accuracy 0.3 \
              --spp 16 --specular-spp 256
run: $(BIN)
	@mkdir -p out
	@echo "rendering scenes/cornell-specular.scene with photon maps (--mode 1994)," \
	    "about 20 CPU seconds"
	./$(BIN) $(RUN_OPTIONS) --no-progress --stats scenes/cornell-specular.scene \
	    -o out/cornell-specular.png 2> out/cornell-specular.stats \
	    || { cat out/cornell-specular.stats; exit 1; }
	@echo "took $$(sed -n 's/^seconds_total=//p' out/cornell-specular.stats) CPU seconds;" \
	    "open out/cornell-specular.png (linear radiance: out/cornell-specular.pfm;" \
	    "statistics: out/cornell-specular.stats)"

# reference/ppm-fig4.c, the program behind a figure of reference/README.md, is built with the
# tests so that it keeps compiling against the code it calls.
$(BUILD)/ppm-fig4: reference/ppm-fig4.c $(LIB_OBJ) $(HEADERS)
	$(CC) $(CFLAGS) -o $@ reference/ppm-fig4.c $(LIB_OBJ) $(LDLIBS)

test: $(BIN) $(BUILD)/run_tests $(BUILD)/ppm-fig4
	PHOTON=./$(BIN) ./$(BUILD)/run_tests

# Only the room spd (tests/test_spd.c), which reads the files from PHOTON_SPD.
test-spd: $(BUILD)/run_tests
	PHOTON_SPD='$(SPD)' ./$(BUILD)/run_tests spd

# Each variant builds in its own directory with its own binary, so none disturbs ./photon.
check:
	$(MAKE) --no-print-directory BUILD=build/gcc BIN=build/gcc/photon CC=gcc EXTRA=-Werror test
	$(MAKE) --no-print-directory BUILD=build/clang BIN=build/clang/photon CC=clang EXTRA=-Werror test
	$(MAKE) --no-print-directory BUILD=build/tcc BIN=build/tcc/photon CC=tcc test
	$(MAKE) --no-print-directory BUILD=build/asan BIN=build/asan/photon CC=gcc OPT="-O1 -g" \
	    EXTRA="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" test
	@for m in direct pt photons 1994 1996 2008 2009; do \
	    case $$m in \
	    photons) work="--spp 2 --photons 20000";; \
	    1994) work="--spp 2 --photons 20000 --gather-rays 32";; \
	    1996) work="--spp 2 --photons 20000 --caustic-photons 20000 --gather-rays 32";; \
	    2008) work="--spp 2 --passes 2 --photons-per-pass 20000";; \
	    2009) work="--passes 2 --photons-per-pass 20000";; \
	    *) work="--spp 2";; \
	    esac; \
	    for b in gcc clang tcc asan; do \
	    build/$$b/photon --no-progress --mode $$m --width 48 --height 32 $$work \
	        scenes/cornell-specular.scene -o build/$$b/determinism-$$m.pfm || exit 1; \
	    cmp build/gcc/determinism-$$m.pfm build/$$b/determinism-$$m.pfm || exit 1; \
	done; done
	@echo "determinism: the gcc, clang, tcc and sanitizer builds render identical bytes in every mode"

# The tiles workload (tests/bench/tiles.sh) runs ./$(BIN) as separate processes.
bench: $(BIN) $(BUILD)/bench
	PHOTON=./$(BIN) PHOTON_SPD='$(SPD)' BENCH_TMP=$(BUILD)/bench-tiles ./$(BUILD)/bench $(ONLY)

# Embree 3 against photon on the rays workload's rays (a development tool, never part of the
# product): refused at once, saying what to install, where the compiler finds no Embree.
EMBREE_LIBS ?= -lembree3
EMBREE_OBJ := $(BUILD)/tests/bench/bench_common.o $(BUILD)/tests/bench/bench_rays.o
bench-embree:
	@printf '#include <embree3/rtcore.h>\n' | $(CC) -E -x c - > /dev/null 2>&1 || { \
	    echo "make bench-embree needs Embree 3's headers and library, which are not installed" \
	        "(Debian, Ubuntu: apt-get install libembree-dev)" >&2; exit 2; }
	@$(MAKE) --no-print-directory $(BUILD)/bench-embree
	PHOTON_SPD='$(SPD)' ./$(BUILD)/bench-embree

$(BUILD)/bench-embree: tests/bench/embree/bench_embree.c $(EMBREE_OBJ) $(LIB_OBJ) $(HEADERS)
	$(CC) $(CFLAGS) -o $@ $< $(EMBREE_OBJ) $(LIB_OBJ) $(EMBREE_LIBS) $(LDLIBS)

# pbrt-v4's SPPM against --mode 2009 at equal CPU seconds (scripts/bench_pbrt.sh; a
# development tool: PBRT names pbrt-v4's pbrt, which the product never needs). Refused at
# once when PBRT is unset or names no program.
PBRT ?=
bench-pbrt:
	@[ -n '$(PBRT)' ] || { echo "make bench-pbrt needs PBRT=PATH, pbrt-v4's pbrt program" \
	    "(github.com/mmp/pbrt-v4, built with cmake), which is not set" >&2; exit 2; }
	@[ -f '$(PBRT)' ] && [ -x '$(PBRT)' ] || { echo "make bench-pbrt: PBRT=$(PBRT) is not" \
	    "an executable file (pbrt-v4's pbrt program)" >&2; exit 2; }
	@$(MAKE) --no-print-directory $(BIN) $(BUILD)/pbrt-channels
	PHOTON=$(call here,$(BIN)) PBRT='$(PBRT)' PBRT_CHANNELS=$(call here,$(BUILD)/pbrt-channels) \
	    sh scripts/bench_pbrt.sh $(ONLY)

# A path as a command: ./NAME when NAME is relative, NAME when it is absolute.
here = $(if $(filter /%,$(1)),$(1),./$(1))

$(BUILD)/pbrt-channels: tests/bench/pbrt/pbrt_channels.c $(LIB_OBJ) $(HEADERS)
	$(CC) $(CFLAGS) -o $@ $< $(LIB_OBJ) $(LDLIBS)

# Blender's Cycles against --mode pt at equal CPU seconds (scripts/bench_cycles.sh; a
# development tool: BLENDER names Blender 3.4 or newer, which the product never needs).
# Refused at once where there is no such program, as bench-pbrt is without pbrt.
BLENDER ?= blender
CYCLES_SPP ?= 16 64 256
bench-cycles:
	@command -v '$(BLENDER)' > /dev/null 2>&1 || { echo "make bench-cycles needs Blender 3.4" \
	    "or newer, and '$(BLENDER)' is not installed (Debian, Ubuntu: apt-get install" \
	    "blender; or BLENDER=PATH)" >&2; exit 2; }
	@$(MAKE) --no-print-directory $(BIN)
	PHOTON=$(call here,$(BIN)) BLENDER='$(BLENDER)' BENCH_CYCLES_SPP='$(CYCLES_SPP)' \
	    sh scripts/bench_cycles.sh $(ONLY)

# The figures README.md states, re-measured and written into it (ONLY=presets, bench, rays,
# pbrt or cycles; rays, pbrt and cycles write into tests/bench/README.md).
figures: $(BIN) $(BUILD)/bench
	sh scripts/figures.sh $(ONLY)

# The reference suite (reference/suite.txt), one render at a time; ONLY=NAME (or
# ONLY="NAME NAME") renders only those, keeping the other rows of reference/suite.md.
reference: $(BIN)
	PHOTON=./$(BIN) sh scripts/reference.sh $(ONLY)

# Every photon mode on the scenes of reference/consistency.txt (ONLY=NAME ..., MODES=...,
# QUALITY=preset; KINDS=defaults or target for one table), the tables into
# reference/suite.md.
consistency: $(BIN)
	PHOTON=./$(BIN) MODES='$(MODES)' QUALITY='$(QUALITY)' KINDS='$(KINDS)' \
	    sh scripts/consistency.sh $(ONLY)

# Whether the stated error holds: each mode that states one on the scenes of
# reference/consistency.txt (ONLY=NAME ..., MODES=...), the table into reference/suite.md.
calibration: $(BIN)
	PHOTON=./$(BIN) MODES='$(MODES)' sh scripts/calibration.sh $(ONLY)

# Fuzz targets (a development tool, not part of the product build): one per reader, the
# option parser, and deflate's round trip. Run
# e.g. build/fuzz/fuzz_nff -max_len=8192 -max_total_time=600 CORPUS_DIR < /dev/null
FUZZ_CC ?= clang
FUZZ_FLAGS = -std=c99 -g -O1 -ffp-contract=off -fsanitize=fuzzer,address,undefined $(WARN)
FUZZ_BIN := $(patsubst tests/fuzz/%.c,build/fuzz/%,$(wildcard tests/fuzz/fuzz_*.c))

fuzz: $(FUZZ_BIN)

build/fuzz/%: tests/fuzz/%.c tests/fuzz/input.c tests/fuzz/input.h $(SRC) $(HEADERS)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_FLAGS) -o $@ $< tests/fuzz/input.c $(SRC) -lm

# Cycles against the pt references (scripts/crosscheck.sh): a development check, not a test.
crosscheck: $(BIN)
	sh scripts/crosscheck.sh $(ONLY)

PREFIX ?= /usr/local
DESTDIR ?=
SCENE_FILES := $(sort $(wildcard scenes/*.* scenes/*/*.*))
SCENE_DIRS := $(sort $(dir $(SCENE_FILES)))

$(BUILD)/photon.1: $(BIN)
	./$(BIN) --manual > $@.tmp && mv $@.tmp $@

install: $(BIN) $(BUILD)/photon.1
	mkdir -p '$(DESTDIR)$(PREFIX)/bin' '$(DESTDIR)$(PREFIX)/share/man/man1'
	cp $(BIN) '$(DESTDIR)$(PREFIX)/bin/photon'
	chmod 755 '$(DESTDIR)$(PREFIX)/bin/photon'
	cp $(BUILD)/photon.1 '$(DESTDIR)$(PREFIX)/share/man/man1/photon.1'
	chmod 644 '$(DESTDIR)$(PREFIX)/share/man/man1/photon.1'
	for d in $(SCENE_DIRS:scenes/%=%); do \
	    mkdir -p '$(DESTDIR)$(PREFIX)/share/photon/'"$$d" || exit 1; done
	for f in $(SCENE_FILES:scenes/%=%); do \
	    cp "scenes/$$f" '$(DESTDIR)$(PREFIX)/share/photon/'"$$f" && \
	    chmod 644 '$(DESTDIR)$(PREFIX)/share/photon/'"$$f" || exit 1; done

uninstall:
	rm -f '$(DESTDIR)$(PREFIX)/bin/photon' '$(DESTDIR)$(PREFIX)/share/man/man1/photon.1'
	for f in $(SCENE_FILES:scenes/%=%); do rm -f '$(DESTDIR)$(PREFIX)/share/photon/'"$$f"; done
	for d in $(sort $(SCENE_DIRS:scenes/%=%)) ''; do \
	    rmdir '$(DESTDIR)$(PREFIX)/share/photon/'"$$d" 2>/dev/null || true; done

clean:
	rm -rf build out $(BIN)
