# scripts/tiles.mk -- an image as tiles that make renders, J at a time, then merges (GNU make).
#
#   make -f scripts/tiles.mk -j2 SCENE=scenes/cornell.scene OUT=cornell.pfm TILES=4 \
#        OPTIONS='--mode pt --spp 16' [WORK=cornell.work] [PHOTON=./photon]
#
# TILES is N (N horizontal bands) or CxR (a grid), cut by tile-windows.sh. Each tile is a
# target, OUT's directory TILE_DIR (OUT with .tiles for .pfm) holding X0_Y0_X1_Y1.pfm with
# its record; OUT is photon merge's. A tile that failed leaves no record (photon writes
# each file whole or not at all, the record last), so running make again renders the
# tiles that are missing, alone, and merges.
#
# WORK=FILE (--mode photons, 1994, 1996) does the mode's global work once: a one-pixel
# render saves it with --save-photons, and every tile reads it with --load-photons.
#
# make knows the tiles' files, not what made them: after editing the scene or changing
# OPTIONS, run the same command with `clean` first (merge refuses a mixture anyway: each
# record keeps the hash of the scene and the options).

PHOTON ?= ./photon
TILES = 4
OPTIONS =
WORK =
TILE_DIR = $(OUT:.pfm=.tiles)
TILE_WINDOWS = $(dir $(lastword $(MAKEFILE_LIST)))tile-windows.sh

ifeq ($(filter %.pfm,$(OUT)),)
$(error OUT=NAME.pfm is needed, with SCENE=FILE)
endif

# One word a tile, X0_Y0_X1_Y1, which names its files and gives its --crop.
ifneq ($(MAKECMDGOALS),clean)
WINDOWS := $(shell $(TILE_WINDOWS) --photon $(PHOTON) $(SCENE) $(TILES) $(OPTIONS) | tr ' ' _)
ifeq ($(WINDOWS),)
$(error tile-windows.sh found no tiles (see above))
endif
endif
RECORDS = $(WINDOWS:%=$(TILE_DIR)/%.pfm.window)

.PHONY: all clean
all: $(OUT)

$(OUT): $(RECORDS)
	$(PHOTON) merge -o $@ $(RECORDS:.window=)

$(TILE_DIR)/%.pfm.window: $(WORK)
	@mkdir -p $(TILE_DIR)
	$(PHOTON) --no-progress $(OPTIONS) $(if $(WORK),--load-photons $(WORK)) \
	    --crop $(subst _, ,$*) -o $(@:.window=) $(SCENE)

ifneq ($(WORK),)
# The global work covers the whole image whatever the window, so one pixel saves it all.
$(WORK):
	@mkdir -p $(TILE_DIR)
	$(PHOTON) --no-progress $(OPTIONS) --crop 0 0 1 1 -o $(TILE_DIR)/work-pixel.pfm \
	    --save-photons $@ $(SCENE)
endif

clean:
	rm -rf $(TILE_DIR) $(OUT) $(OUT:.pfm=.png) $(OUT:.pfm=.ppm) $(WORK)
