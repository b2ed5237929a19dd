/*
 * app/merge.h -- `photon merge`: crops rendered apart, put back into the whole image.
 *
 *   photon merge -o FULL.pfm TILE.pfm [TILE.pfm ...] [--exposure E]
 *
 * Each TILE.pfm is a render with --crop, and TILE.pfm.window its record (tile.h). The
 * tiles must be windows of one image: the same image size and the same hash (scene bytes,
 * mode, seed, options), none made with --time-limit, each PFM the size of its window and
 * the very pixels its record was written with (tile.h), no two overlapping, and together covering every pixel. Then FULL.pfm is the whole image,
 * byte for byte the file a render without --crop writes (README: a crop renders
 * bit-identically to the same window of the whole image), and its display image is beside
 * it: FULL.png, or FULL.ppm for -o FULL.ppm (-o as for a render, option_values.h read_output;
 * --exposure too); a crop's record FULL.pfm.window left by an earlier render is removed.
 * Anything else exits 2 with a message naming the file, the
 * overlap or the missing windows, and writes nothing.
 */
#ifndef PHOTON_MERGE_H
#define PHOTON_MERGE_H

#include "../base/option_equals.h"

/* argv[0] is "merge". Returns the exit status: 0, or 2 for bad input or an output that
 * cannot be written (the message is printed). */
int merge_command(int argc, char **argv);

/* Its options, for --NAME=VALUE (app/commands.h); a NULL name ends them. */
extern const struct option_arity merge_options[];

#endif
