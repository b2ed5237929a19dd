/*
 * image/error_image.c -- block bounds and the summary of an error image (error_image.h).
 */
#include "error_image.h"

#include <assert.h>
#include <math.h>

#include "compare.h"

struct block_bound block_bound(const struct image *image, const struct image *error, int x0,
                               int y0)
{
    assert(image->width == error->width && image->height == error->height);
    int x1 = x0 + ERROR_BLOCK < image->width ? x0 + ERROR_BLOCK : image->width;
    int y1 = y0 + ERROR_BLOCK < image->height ? y0 + ERROR_BLOCK : image->height;
    double sum = 0.0, bound2 = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            double b = vec3_luminance(image_get(error, x, y));
            sum += vec3_luminance(image_get(image, x, y));
            bound2 += b * b;
        }
    double n = (double)(x1 - x0) * (double)(y1 - y0);
    struct block_bound r = {sum / n, sqrt(bound2) / n};
    return r;
}

struct error_summary error_summary(const struct image *image, const struct image *error,
                                   double confidence)
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
    for (int y0 = 0; y0 < image->height; y0 += ERROR_BLOCK)
        for (int x0 = 0; x0 < image->width; x0 += ERROR_BLOCK) {
            struct block_bound b = block_bound(image, error, x0, y0);
            if (b.mean < ERROR_DARK_FLOOR)
                continue;
            s.n_blocks++;
            s.within_1 += b.bound <= 0.01 * b.mean;
            s.within_3 += b.bound <= 0.03 * b.mean;
        }
    return s;
}
