/*
 * image/display.c -- the display image written beside every PFM: the 8-bit sRGB bytes
 * that the PNG (png.c) and the PPM (ppm.c) both carry, and the pair of files every
 * image-making command writes (image.h).
 *
 * A channel byte is value * exposure, clamped to [0, 1] (no tone mapping), encoded with
 * the sRGB transfer function (IEC 61966-2-1) and rounded to the nearest of 256 levels.
 * The value is first rounded to the float the PFM keeps of it, so that the display image
 * of a render and the one `photon merge` makes from its PFM tiles agree byte for byte
 * (a double a hair above a level's boundary can round to a float below it).
 */
#include "image.h"

#include <assert.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/output.h"
#include "png.h"

/* sRGB encoding of a linear value: 12.92 c on the linear segment c <= 0.0031308, else
 * 1.055 c^(1/2.4) - 0.055; e is in [0, 1], so the byte is in 0..255. */
static unsigned char srgb_byte(double linear)
{
    double c = fmax(0.0, fmin(1.0, linear));
    double e = c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
    return (unsigned char)floor(255.0 * e + 0.5);
}

unsigned char *display_encode(const struct image *img, double exposure)
{
    assert(isfinite(exposure) && exposure >= 0); /* the caller checked the option */
    unsigned char *rgb = xmalloc((size_t)img->width * (size_t)img->height, 3, "display image");
    size_t i = 0;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            struct vec3 p = image_get(img, x, y);
            rgb[i++] = srgb_byte(pfm_stored_value(p.x) * exposure);
            rgb[i++] = srgb_byte(pfm_stored_value(p.y) * exposure);
            rgb[i++] = srgb_byte(pfm_stored_value(p.z) * exposure);
        }
    return rgb;
}

const char *display_suffix(enum display_format format)
{
    return format == DISPLAY_PPM ? ".ppm" : ".png";
}

/* pfm_name, which ends in ".pfm" or ".exr", with the ending of display in its place:
 * owned by the caller (xfree). */
static char *display_name(const char *pfm_name, enum display_format display)
{
    size_t n = strlen(pfm_name);
    assert(n >= 4 && (strcmp(pfm_name + n - 4, ".pfm") == 0 || image_name_is_exr(pfm_name)));
    char *name = xstrdup(pfm_name);
    strcpy(name + n - 4, display_suffix(display)); /* as long as ".pfm" */
    return name;
}

void image_declare_pair(const char *pfm_name, enum display_format display, const char *role,
                        const char *display_role)
{
    char *name = display_name(pfm_name, display);
    output_declare(pfm_name, role);
    output_declare(name, display_role);
    xfree(name);
}

int image_write_pair(const char *pfm_name, enum display_format display,
                     const struct image *img, double exposure, struct error *err)
{
    char *name = display_name(pfm_name, display);
    int status = image_write(pfm_name, img, err); /* .pfm or .exr */
    if (status == 0)
        status = display == DISPLAY_PPM ? ppm_write(name, img, exposure, err)
                                        : png_write(name, img, exposure, err);
    xfree(name);
    return status;
}
