/*
 * image/ppm.c -- binary PPM (P6) for looking at a render; the PFM is the image of record.
 *
 * "P6\n<width> <height>\n255\n", then one byte per channel, rows top to bottom, each row
 * left to right. A channel byte is value * exposure, clamped to [0, 1] (no tone mapping),
 * encoded with the sRGB transfer function (IEC 61966-2-1) and rounded to the nearest of
 * 256 levels. The value is first rounded to the float the PFM keeps of it, so that the PPM
 * of a render and the PPM `photon merge` makes from its PFM tiles agree byte for byte
 * (a double a hair above a level's boundary can round to a float below it). Written
 * atomically through output_open()/output_commit().
 */
#include "image.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"

/* sRGB encoding of a linear value: 12.92 c on the linear segment c <= 0.0031308, else
 * 1.055 c^(1/2.4) - 0.055; e is in [0, 1], so the byte is in 0..255. */
static int srgb_byte(double linear)
{
    double c = fmax(0.0, fmin(1.0, linear));
    double e = c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
    return (int)floor(255.0 * e + 0.5);
}

int ppm_write(const char *name, const struct image *img, double exposure, struct error *err)
{
    assert(isfinite(exposure) && exposure >= 0); /* the caller checked the option */
    FILE *f = output_open(name, err);
    if (f == NULL)
        return -1;
    fprintf(f, "P6\n%d %d\n255\n", img->width, img->height);
    for (int y = 0; y < img->height; y++) {
        for (int x = 0; x < img->width; x++) {
            struct vec3 p = image_get(img, x, y);
            struct vec3 v = vec3_scale(vec3(pfm_stored_value(p.x), pfm_stored_value(p.y),
                                            pfm_stored_value(p.z)), exposure);
            putc(srgb_byte(v.x), f);
            putc(srgb_byte(v.y), f);
            putc(srgb_byte(v.z), f);
        }
    }
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}

int image_write_pair(const char *pfm_name, const struct image *img, double exposure,
                     struct error *err)
{
    size_t n = strlen(pfm_name);
    assert(n >= 4 && strcmp(pfm_name + n - 4, ".pfm") == 0);
    char *ppm_name = xstrdup(pfm_name);
    strcpy(ppm_name + n - 4, ".ppm");
    int status = pfm_write(pfm_name, img, err) < 0 || ppm_write(ppm_name, img, exposure, err) < 0
                     ? -1
                     : 0;
    free(ppm_name);
    return status;
}
