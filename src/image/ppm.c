/*
 * image/ppm.c -- binary PPM (P6), the display image on request (-o NAME.ppm) and
 * `photon compare --diff`'s picture; the PFM is the image of record.
 *
 * "P6\n<width> <height>\n255\n", then one byte per channel, rows top to bottom, each row
 * left to right: the bytes display_encode_row() makes (display.c), the same as the PNG's.
 * Written atomically through output_open()/output_commit().
 */
#include "image.h"


#include "../base/alloc.h"
#include "../base/output.h"

int ppm_write(const char *name, const struct image *img, double exposure, struct error *err)
{
    FILE *f = output_open(name, err);
    if (f == NULL)
        return -1;
    fprintf(f, "P6\n%d %d\n255\n", img->width, img->height);
    unsigned char *rgb = xmalloc((size_t)img->width, 3, "display row");
    for (int y = 0; y < img->height; y++) {
        display_encode_row(img, y, exposure, rgb);
        fwrite(rgb, 3, (size_t)img->width, f);
    }
    xfree(rgb);
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}
