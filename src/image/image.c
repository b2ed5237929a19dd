/*
 * image/image.c -- the image buffer: creation and release (see image.h).
 *
 * An image owns its pixel array; image_free() releases both. Sizes are the caller's to
 * check against MAX_IMAGE_SIDE first (readers refuse larger ones as bad input), so here
 * they are asserted, not reported. Files live elsewhere: pfm.c, display.c, png.c, ppm.c.
 */
#include "image.h"

#include <assert.h>

#include "../base/alloc.h"

struct image *image_create(int width, int height)
{
    assert(width >= 1 && width <= MAX_IMAGE_SIDE);
    assert(height >= 1 && height <= MAX_IMAGE_SIDE);
    size_t n_pixels = (size_t)width * (size_t)height;
    struct image *img = xmalloc(1, sizeof *img, "image");
    img->width = width;
    img->height = height;
    img->pixels = xmalloc(n_pixels, sizeof *img->pixels, "image pixels");
    for (size_t i = 0; i < n_pixels; i++)
        img->pixels[i] = vec3_zero();
    return img;
}

struct image *image_window(const struct image *img, int x0, int y0, int width, int height)
{
    assert(x0 >= 0 && y0 >= 0 && x0 + width <= img->width && y0 + height <= img->height);
    struct image *window = image_create(width, height);
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            image_set(window, x, y, image_get(img, x0 + x, y0 + y));
    return window;
}

void image_free(struct image *img)
{
    if (img == NULL)
        return;
    xfree(img->pixels);
    xfree(img);
}
