/*
 * image/ppm.c -- binary PPM (P6), the display image on request (-o NAME.ppm) and
 * `photon compare --diff`'s picture; the PFM is the image of record.
 *
 * "P6\n<width> <height>\n255\n", then one byte per channel, rows top to bottom, each row
 * left to right: the bytes display_encode_row() makes (display.c), the same as the PNG's.
 * ppm_write_bytes() writes a picture's bytes made beforehand (false_colour.h) the same way.
 * Written atomically through output_open()/output_commit().
 */
#include "image.h"

#include <string.h>

#include "../base/alloc.h"
#include "../base/output.h"

/* The header, then each row as row(context, y, rgb) makes it (png.c's row_maker). */
static int write_rows(const char *name, int width, int height,
                      void (*row)(const void *context, int y, unsigned char *rgb),
                      const void *context, struct error *err)
{
    FILE *f = output_open(name, err);
    if (f == NULL)
        return -1;
    fprintf(f, "P6\n%d %d\n255\n", width, height);
    unsigned char *rgb = xmalloc((size_t)width, 3, "display row");
    for (int y = 0; y < height; y++) {
        row(context, y, rgb);
        fwrite(rgb, 3, (size_t)width, f);
    }
    xfree(rgb);
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}

/* The image and exposure ppm_write() was given. */
struct exposed {
    const struct image *img;
    double exposure;
};

static void exposed_row(const void *context, int y, unsigned char *rgb)
{
    const struct exposed *e = context;
    display_encode_row(e->img, y, e->exposure, rgb);
}

int ppm_write(const char *name, const struct image *img, double exposure, struct error *err)
{
    struct exposed e = {img, exposure};
    return write_rows(name, img->width, img->height, exposed_row, &e, err);
}

/* The bytes ppm_write_bytes() was given. */
struct bytes {
    int width;
    const unsigned char *rgb;
};

static void bytes_row(const void *context, int y, unsigned char *rgb)
{
    const struct bytes *b = context;
    size_t row = 3 * (size_t)b->width;
    memcpy(rgb, b->rgb + (size_t)y * row, row);
}

int ppm_write_bytes(const char *name, int width, int height, const unsigned char *rgb,
                    struct error *err)
{
    struct bytes b = {width, rgb};
    return write_rows(name, width, height, bytes_row, &b, err);
}
