/*
 * image/png.h -- PNG files of the display image: 8-bit RGB, uncompressed (png.c).
 */
#ifndef PHOTON_PNG_H
#define PHOTON_PNG_H

#include "image.h"

/* Writes img as an 8-bit RGB PNG (colour type 2) of the bytes display_encode() makes (the
 * PPM's), deflate in stored blocks, atomically through output_open()/output_commit().
 * -1 with *err filled when the file cannot be written. exposure: as display_encode()'s. */
int png_write(const char *name, const struct image *img, double exposure, struct error *err);

/* The same file of bytes already made: rgb holds width x height pixels, R G B each, rows
 * from the top (a false-colour picture, false_colour.h). width and height are 1 to
 * MAX_IMAGE_SIDE. -1 with *err filled when the file cannot be written. */
int png_write_bytes(const char *name, int width, int height, const unsigned char *rgb,
                    struct error *err);

#endif
