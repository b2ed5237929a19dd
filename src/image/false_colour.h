/*
 * image/false_colour.h -- an image shown in false colour: one number per pixel through a
 * perceptual colour map (colour_map.h), with the map's scale drawn beside it as a colour
 * bar and its values in figures (font.h), so that the picture says what it shows. Made
 * by `photon convert --false-colour` and `photon compare --diff`. Definitions, layout
 * and the default range in false_colour.c.
 */
#ifndef PHOTON_FALSE_COLOUR_H
#define PHOTON_FALSE_COLOUR_H

#include <stddef.h>

#include "image.h"

/* The default range's top: this percentile of the pixels' numbers (false_colour.c). */
#define FALSE_COLOUR_PERCENTILE 99
/* The default range's bottom with --log: the top over this (three decades). */
#define FALSE_COLOUR_LOG_DECADES 1000.0

/* How the numbers become colours, and how the scale is labelled. */
struct false_colour {
    double min, max; /* min's colour is the map's first, max's its last; below and above
                        take the ends' colours. min < max, both finite               */
    int log;         /* 1: by log10 of the number (0 < min; numbers <= 0 are min's
                        colour); 0: linearly                                            */
    int percent;     /* 1: labels in percent, the number x 100 (relative errors)        */
    int percentile;  /* 1: max is the default top: its label ends " p99"               */
};

/* The number a pixel shows: the largest of its R, G and B (false_colour.c says why). */
double false_colour_number(struct vec3 pixel);

/* Fills in fc's ends that were not given (has_min, has_max 0) from img's numbers, by the
 * default rule of false_colour.c; fc->log and fc->percent are set already, and given
 * ends are in fc and checked by the caller (min < max; with log, 0 < min). */
void false_colour_range(const struct image *img, int has_min, int has_max,
                        struct false_colour *fc);

/* A label of the scale: value as "%.3g" with its exponent without '+' and leading zeros
 * ("1e-5"), in percent with a '%' when fc->percent; into text[size]. */
void false_colour_label(double value, const struct false_colour *fc, char *text,
                        size_t size);

/* Where things are in a picture of an image width x height whose longest label has
 * label_chars characters (false_colour.c's layout); x and y from the top left. */
struct false_colour_layout {
    int scale;           /* every length below is in units of this many pixels       */
    int width, height;   /* the picture's                                            */
    int bar_x0, bar_x1;  /* the bar's columns, [bar_x0, bar_x1)                       */
    int bar_y0, bar_y1;  /* and rows: max's colour at bar_y0, min's at bar_y1 - 1     */
    int label_x;         /* the labels' left column                                  */
};
struct false_colour_layout false_colour_layout(int width, int height, int label_chars);

/* A picture: width x height pixels of R G B bytes, rows from the top. */
struct picture {
    int width, height;
    unsigned char *rgb; /* owned */
};

/* img in false colour, with its scale; the caller frees it (picture_free). */
struct picture false_colour_picture(const struct image *img, const struct false_colour *fc);
void picture_free(struct picture *p);

/* Writes p as a PPM when name ends in ".ppm", else as a PNG, atomically (png.h); -1 with
 * *err filled when it cannot be written. */
int picture_write(const char *name, const struct picture *p, struct error *err);

#endif
