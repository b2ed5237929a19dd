/*
 * image/error_image.c -- block bounds and the summary of an error image (error_image.h).
 */
#include "error_image.h"

#include <assert.h>
#include <math.h>

#include "compare.h"

/* The mean luminance of image over [x0, x1) x [y0, y1) and the bound on it. */
static void block_bound(const struct image *image, const struct image *error, int x0, int y0,
                        int x1, int y1, double *mean, double *bound)
{
    double sum = 0.0, bound2 = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            double b = vec3_luminance(image_get(error, x, y));
            sum += vec3_luminance(image_get(image, x, y));
            bound2 += b * b;
        }
    double n = (double)(x1 - x0) * (double)(y1 - y0);
    *mean = sum / n;
    *bound = sqrt(bound2) / n;
}

struct block_count blocks_within(const struct image *image, const struct image *error, int x0,
                                 int y0, double e)
{
    assert(image->width == error->width && image->height == error->height);
    struct block_count count = {0, 0, -1, -1};
    /* the grid's first row and column start at or before the image's top left pixel */
    for (int by = y0 - y0 % ERROR_BLOCK; by < y0 + image->height; by += ERROR_BLOCK)
        for (int bx = x0 - x0 % ERROR_BLOCK; bx < x0 + image->width; bx += ERROR_BLOCK) {
            int u0 = bx > x0 ? bx - x0 : 0, v0 = by > y0 ? by - y0 : 0;
            int u1 = bx + ERROR_BLOCK - x0 < image->width ? bx + ERROR_BLOCK - x0 : image->width;
            int v1 = by + ERROR_BLOCK - y0 < image->height ? by + ERROR_BLOCK - y0
                                                           : image->height;
            double mean, bound;
            block_bound(image, error, u0, v0, u1, v1, &mean, &bound);
            if (mean < ERROR_DARK_FLOOR)
                continue;
            count.n_blocks++;
            if (bound <= e * mean)
                count.within++;
            else if (count.missed_x < 0) {
                count.missed_x = u0 + x0;
                count.missed_y = v0 + y0;
            }
        }
    return count;
}

struct error_summary error_summary(const struct image *image, const struct image *error,
                                   double confidence, int x0, int y0)
{
    struct error_summary s = {0.0, 0, 0, 0};
    double z = normal_critical_two_sided(1.0 - confidence);
    size_t n = (size_t)image->width * (size_t)image->height;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            double sigma = vec3_get(error->pixels[i], c) / z, v = vec3_get(image->pixels[i], c);
            s.relmse += sigma * sigma / (v * v + 1e-2);
        }
    s.relmse /= 3.0 * (double)n;
    struct block_count one = blocks_within(image, error, x0, y0, 0.01);
    struct block_count three = blocks_within(image, error, x0, y0, 0.03);
    s.n_blocks = one.n_blocks;
    s.within_1 = one.within;
    s.within_3 = three.within;
    return s;
}
