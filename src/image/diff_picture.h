/*
 * image/diff_picture.h -- `photon compare --diff`'s picture: how far a test image is from
 * its reference at each pixel, in false colour with its scale (diff_picture.c).
 */
#ifndef PHOTON_DIFF_PICTURE_H
#define PHOTON_DIFF_PICTURE_H

#include "image.h"

/* The floor under the reference in the relative error: this share of its mean value. */
#define DIFF_FLOOR 0.01

/* The error of test image a against reference b (same size, finite values) at each
 * pixel, per channel: relative, |a - b| / max(b, floor), or with absolute != 0, |a - b|
 * (diff_picture.c). */
struct image *diff_image(const struct image *a, const struct image *b, int absolute);

/* diff_image() written as a false-colour picture with its scale (false_colour.h) to name,
 * a PPM for a name ending in ".ppm", else a PNG; relative errors labelled in percent. -1
 * with *err filled when it cannot be written. */
int diff_picture_write(const char *name, const struct image *a, const struct image *b,
                       int absolute, struct error *err);

#endif
