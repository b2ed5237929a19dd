/*
 * image/diff_picture.c -- `photon compare --diff`'s picture (diff_picture.h).
 *
 * Relative by default, since a renderer's error is judged against the light it should
 * have: 0.01 off where the reference is 0.02 is a far worse pixel than 0.01 off where it
 * is 10, and |a - b| shows the second brighter. The error of channel c is
 * |a_c - b_c| / max(b_c, floor), floor = DIFF_FLOOR (1%) of b's mean over its pixels and
 * channels, so that a pixel black in the reference shows its error against the image's
 * level (0.01 off in a black corner of an image of mean 0.5 is 200%) rather than as +Inf;
 * when b's mean is not above 0 the floor is 1, and the error absolute. The picture shows
 * the worst channel's error (false_colour.c says why), from 0 to the 99th percentile of
 * the pixels' errors, labelled in percent. --diff-absolute shows |a - b| instead, in the
 * image's own units.
 */
#include "diff_picture.h"

#include <string.h>

#include "false_colour.h"

struct image *diff_image(const struct image *a, const struct image *b, int absolute)
{
    struct image *diff = image_create(a->width, a->height);
    size_t n_pixels = (size_t)a->width * (size_t)a->height;
    double sum = 0;
    for (size_t i = 0; i < n_pixels; i++)
        sum += b->pixels[i].x + b->pixels[i].y + b->pixels[i].z;
    double mean = sum / (3.0 * (double)n_pixels);
    double least = mean > 0 ? DIFF_FLOOR * mean : 1.0; /* the floor */
    for (size_t i = 0; i < n_pixels; i++) {
        struct vec3 d = vec3_sub(a->pixels[i], b->pixels[i]), r = b->pixels[i];
        struct vec3 s = absolute ? vec3(1, 1, 1)
                                 : vec3(fmax(r.x, least), fmax(r.y, least), fmax(r.z, least));
        diff->pixels[i] = vec3(fabs(d.x) / s.x, fabs(d.y) / s.y, fabs(d.z) / s.z);
    }
    return diff;
}

int diff_picture_write(const char *name, const struct image *a, const struct image *b,
                       int absolute, struct error *err)
{
    struct image *diff = diff_image(a, b, absolute);
    struct false_colour fc;
    memset(&fc, 0, sizeof fc);
    fc.percent = !absolute;
    false_colour_range(diff, 0, 0, &fc);
    struct picture p = false_colour_picture(diff, &fc);
    int status = picture_write(name, &p, err);
    picture_free(&p);
    image_free(diff);
    return status;
}
