/*
 * app/tile.h -- the record beside a crop's PFM that lets `photon merge` put it back.
 *
 * A render with --crop writes FILE.pfm.window beside FILE.pfm (and its display image), six
 * lines of text in this order:
 *
 *   photon-window 2                    the format and its version
 *   window X0 Y0 X1 Y1                 the crop, [X0, X1) x [Y0, Y1), (0, 0) at the top left
 *   image WIDTH HEIGHT                 the whole image it is a window of
 *   hash fnv1a64 HHHHHHHHHHHHHHHH      16 lower-case hex digits: what made the pixels
 *   pixels fnv1a64 HHHHHHHHHHHHHHHH    the pixels themselves (tile_pixels_hash)
 *   time-limit SECONDS                 the render's --time-limit, 0 for none
 *
 * The pixels' hash binds the record to the one PFM it was written with: a --checkpoint
 * rewrites the PFM alone, and a render that ends before its record (a signal, a failed
 * write) may leave an earlier run's record beside a new PFM; merge reads every tile's PFM
 * and refuses one whose pixels are not those its record describes. Version 1 had no such
 * line, and is refused.
 *
 * The hash is FNV-1a, 64 bits (base/hash.h), over every line the scene readers read from
 * the scene file and the files it includes and imports (scene.h, source_hash), then this
 * program's version and every option that changes pixels (options_hash): two tiles with the
 * same hash come from the same scene bytes, mode, seed and settings, so by the determinism
 * README states they are windows of one image. --time-limit cannot be hashed that way (it
 * makes pixels depend on the machine's speed), so it is kept on a line of its own and merge
 * refuses tiles that had one.
 *
 * Why a file beside the PFM, not a '#' line in its header: PFM has no comment syntax, and
 * netpbm's pfmtopam (11.1) refuses a header with a comment line wherever it stands
 * (scripts/README.md), so the tile stays a plain PFM any reader takes.
 */
#ifndef PHOTON_TILE_H
#define PHOTON_TILE_H

#include <stdint.h>

#include "../base/error.h"

struct image;

#define TILE_RECORD_SUFFIX ".window" /* appended to the PFM's name */
#define TILE_RECORD_VERSION 2        /* the number on the first line */

struct tile_record {
    int x0, y0, x1, y1; /* the window: 0 <= x0 < x1 <= width, 0 <= y0 < y1 <= height    */
    int width, height;  /* the whole image's size, each 1..MAX_IMAGE_SIDE               */
    uint64_t hash;      /* FNV-1a of the scene's lines and the pixel-changing options   */
    uint64_t pixels;    /* tile_pixels_hash() of the PFM's pixels                        */
    double time_limit;  /* the render's --time-limit in CPU seconds, 0 = none            */
};

/* FNV-1a 64 of the pixels as the PFM keeps them: each channel rounded to a float, its 32
 * bits lowest byte first, R, G, B, pixel by pixel in rows from the top. The same from the
 * image a render writes and from the PFM merge reads back (floats widen exactly). */
uint64_t tile_pixels_hash(const struct image *image);

/* Declares pfm_name + TILE_RECORD_SUFFIX as an output of the command (base/output.h). */
void tile_record_declare(const char *pfm_name);

/* Writes pfm_name + TILE_RECORD_SUFFIX, whole or not at all (output_open). -1 with *err
 * filled when it cannot be written. */
int tile_record_write(const char *pfm_name, const struct tile_record *r, struct error *err);

/* Removes the record beside pfm_name when there is one: a whole render (no --crop) calls
 * it once its PFM is written, so that a record left there by an earlier crop of the same
 * name cannot make merge take the whole image for that crop. Only a record is removed:
 * a file that tile_record_read() takes whole. Anything else of that name (a scene, a
 * note, a directory, a file that cannot be read) is the user's and is left, as merge
 * refuses it anyway. -1 with *err filled when the record cannot be removed. */
int tile_record_remove(const char *pfm_name, struct error *err);

/* Reads the record beside pfm_name into *r. -1 with *err ("FILE.window:LINE: message")
 * when it is missing, of another version, malformed, or its window is not inside its
 * image; *r is then unspecified. */
int tile_record_read(const char *pfm_name, struct tile_record *r, struct error *err);

#endif
