/*
 * image/image.h -- a linear RGB image in double precision, and its files.
 *
 * Pixels are stored row by row with row 0 at the TOP of the picture (as a camera sees
 * it); the PFM format stores rows bottom to top, and pfm.c alone does that flip.
 * Values are linear radiance (W sr^-1 m^-2 per channel in the scene's units), never
 * clamped or tone mapped here.
 */
#ifndef PHOTON_IMAGE_H
#define PHOTON_IMAGE_H

#include "../base/error.h"
#include "../base/vec3.h"

/* Documented limit on either side of an image: 1 << 15 pixels. Larger sizes are refused
 * as bad input before anything is allocated (32768^2 pixels of 24 bytes is already 24 GiB). */
#define MAX_IMAGE_SIDE 32768

struct image {
    int width, height;   /* >= 1 each, <= MAX_IMAGE_SIDE */
    struct vec3 *pixels; /* owned; width * height, row-major, row 0 at the top */
};

struct image *image_create(int width, int height); /* all pixels zero */
void image_free(struct image *img);                 /* NULL is a no-op */

static inline struct vec3 image_get(const struct image *img, int x, int y)
{
    return img->pixels[(size_t)y * (size_t)img->width + (size_t)x];
}
static inline void image_set(struct image *img, int x, int y, struct vec3 value)
{
    img->pixels[(size_t)y * (size_t)img->width + (size_t)x] = value;
}

/* PFM ("PF", little-endian, negative scale, rows bottom to top), written atomically
 * through output_open()/output_commit(). Each double is rounded to the nearest float. */
int pfm_write(const char *name, const struct image *img, struct error *err);
/* Reads a colour PFM of either byte order. NULL with *err filled for anything malformed. */
struct image *pfm_read(const char *name, struct error *err);

/* The value a PFM keeps of v: v rounded to the nearest binary32 (clamped to +-FLT_MAX). */
double pfm_stored_value(double v);

/* Binary PPM (P6) for display: each channel as the PFM keeps it (pfm_stored_value), times
 * exposure, clamped to [0, 1], sRGB-encoded, 8 bits; so a PPM made from a PFM read back
 * (photon merge) has the same bytes as the one written beside it. */
int ppm_write(const char *name, const struct image *img, double exposure, struct error *err);

/* The pair every image-making command writes: the PFM pfm_name, which ends in ".pfm" (the
 * caller checked), and the PPM of the same name ending in ".ppm" beside it, each written
 * whole or not at all. */
int image_write_pair(const char *pfm_name, const struct image *img, double exposure,
                     struct error *err);

#endif
