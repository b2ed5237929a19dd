/*
 * image/ppm.c -- binary PPM (P6), the display image on request (-o NAME.ppm) and
 * `photon compare --diff`'s picture; the PFM is the image of record.
 *
 * "P6\n<width> <height>\n255\n", then one byte per channel, rows top to bottom, each row
 * left to right: the bytes display_encode() makes (display.c), the same as the PNG's;
 * ppm_write_bytes() writes any picture's bytes made beforehand (false_colour.h).
 * Written atomically through output_open()/output_commit().
 */
#include "image.h"

#include "../base/alloc.h"
#include "../base/output.h"

int ppm_write_bytes(const char *name, int width, int height, const unsigned char *rgb,
                    struct error *err)
{
    FILE *f = output_open(name, err);
    if (f == NULL)
        return -1;
    fprintf(f, "P6\n%d %d\n255\n", width, height);
    fwrite(rgb, 3 * (size_t)width, (size_t)height, f);
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}

int ppm_write(const char *name, const struct image *img, double exposure, struct error *err)
{
    unsigned char *rgb = display_encode(img, exposure);
    int status = ppm_write_bytes(name, img->width, img->height, rgb, err);
    xfree(rgb);
    return status;
}
