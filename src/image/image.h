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
/* A copy of img's width x height pixels from (x0, y0), a window inside it. */
struct image *image_window(const struct image *img, int x0, int y0, int width, int height);

static inline struct vec3 image_get(const struct image *img, int x, int y)
{
    return img->pixels[(size_t)y * (size_t)img->width + (size_t)x];
}
static inline void image_set(struct image *img, int x, int y, struct vec3 value)
{
    img->pixels[(size_t)y * (size_t)img->width + (size_t)x] = value;
}

/* PFM ("PF", little-endian, negative scale, rows bottom to top), written atomically
 * through output_open()/output_commit(). Each double is rounded to the nearest float; an
 * image with a value beyond the float range is refused (-1, *err a failed write). */
int pfm_write(const char *name, const struct image *img, struct error *err);
/* Reads a colour PFM of either byte order. NULL with *err filled for anything malformed,
 * and for a value that is NaN or infinite. */
struct image *pfm_read(const char *name, struct error *err);
/* pfm_read() for an error image (modes/pixel_error.h), which may hold +Inf: a bound that
 * cannot be stated. NaN and -Inf are refused still. */
struct image *pfm_read_bounds(const char *name, struct error *err);

/* The one entry for reading an image file, whatever its format: a PFM (above) or a
 * scanline OpenEXR (exr.h), told apart by the file's first bytes. The rules of pfm_read()
 * and pfm_read_bounds() hold for both. */
struct image *image_read(const char *name, struct error *err);
struct image *image_read_bounds(const char *name, struct error *err);

/* The one entry for writing an image's floats: an OpenEXR file (exr.h: FLOAT RGB, ZIP)
 * when name ends in ".exr", a PFM (pfm_write) otherwise. */
int image_write(const char *name, const struct image *img, struct error *err);
/* Whether name ends in ".exr". */
int image_name_is_exr(const char *name);

/* Refuses an image with a value beyond the float range before a byte of it is written
 * (-1, *err a failed write naming the pixel): a file of floats (format: "a PFM's") cannot
 * hold it, and a clamp to FLT_MAX would be a silently wrong image. 0 when all fit. */
int image_check_float_range(const char *name, const struct image *img, const char *format,
                            struct error *err);

/* The value a PFM keeps of v: v rounded to the nearest binary32 (clamped to +-FLT_MAX). */
double pfm_stored_value(double v);

/* The display image written beside the PFM: an 8-bit sRGB picture for people to look at. */
enum display_format {
    DISPLAY_PNG, /* png.c: RGB PNG, the default */
    DISPLAY_PPM  /* ppm.c: binary PPM (P6), asked for by -o NAME.ppm */
};

/* img as the display image shows it, a new array (the caller frees it) of width x height
 * pixels, R G B each, rows from the top: each channel as the PFM keeps it
 * (pfm_stored_value), times exposure, clamped to [0, 1], sRGB-encoded, rounded to 8 bits;
 * so the display image made from a PFM read back (photon merge) has the same bytes as the
 * one written beside it. exposure is finite and >= 0 (the caller checked). */
unsigned char *display_encode(const struct image *img, double exposure);

/* The file-name ending of format: ".png" or ".ppm", as long as ".pfm". */
const char *display_suffix(enum display_format format);

/* Binary PPM (P6) of the bytes display_encode() makes, written atomically through
 * output_open()/output_commit(). -1 with *err filled when the file cannot be written. */
int ppm_write(const char *name, const struct image *img, double exposure, struct error *err);
/* The same file of bytes already made, as png_write_bytes() (png.h) takes them. */
int ppm_write_bytes(const char *name, int width, int height, const unsigned char *rgb,
                    struct error *err);

/* Declares the pair image_write_pair() writes as outputs of the command (base/output.h):
 * pfm_name, ending in ".pfm" or ".exr", under role ("-o"), and the display image beside it under
 * display_role ("the PNG beside -o"). */
void image_declare_pair(const char *pfm_name, enum display_format display, const char *role,
                        const char *display_role);

/* The pair every image-making command writes: the PFM pfm_name, which ends in ".pfm" (the
 * caller checked; or the OpenEXR file, ending in ".exr": image_write), then the display image of the same name ending in display_suffix()
 * beside it, each written whole or not at all. -1 with *err filled when either cannot be
 * written (the display image is not tried when the PFM failed). */
int image_write_pair(const char *pfm_name, enum display_format display,
                     const struct image *img, double exposure, struct error *err);

#endif
