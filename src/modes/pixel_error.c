/*
 * modes/pixel_error.c -- pooled_error_image() (pixel_error.h).
 */
#include "pixel_error.h"

#include <assert.h>
#include <math.h>

#include "../image/compare.h"

/* Pixel i's sum of squared deviations from its mean in channel c: (n - 1) s^2. Rounding
 * can make the difference slightly negative, never the truth. */
static double squared_deviations(const struct pixel_sums *sums, size_t i, int c)
{
    double mean = sums->sum[3 * i + c] / sums->n[i];
    return fmax(0.0, sums->sum2[3 * i + c] - sums->n[i] * mean * mean);
}

/* Pixel i's mean of channel c and that mean's variance s^2 / n. */
static double pixel_mean(const struct pixel_sums *sums, size_t i, int c)
{
    return sums->sum[3 * i + c] / sums->n[i];
}

static double mean_variance(const struct pixel_sums *sums, size_t i, int c)
{
    return squared_deviations(sums, i, c) / (sums->n[i] - 1.0) / sums->n[i];
}

/* The pooled s^2 of channel c over the pixels within ERROR_POOL_RADIUS of pixel i at
 * (x, y), inside the window, whose means agree with i's (pixel_error.h): their squared
 * deviations over their degrees of freedom. i itself always agrees. */
static double pooled_sample_variance(const struct pixel_sums *sums, size_t i, int x, int y,
                                     int c)
{
    double deviations = 0.0, freedom = 0.0;
    for (int v = y - ERROR_POOL_RADIUS; v <= y + ERROR_POOL_RADIUS; v++)
        for (int u = x - ERROR_POOL_RADIUS; u <= x + ERROR_POOL_RADIUS; u++) {
            if (u < 0 || v < 0 || u >= sums->width || v >= sums->height)
                continue;
            size_t j = (size_t)v * (size_t)sums->width + (size_t)u;
            double d = pixel_mean(sums, j, c) - pixel_mean(sums, i, c);
            double agree = POOL_AGREEMENT_Z * POOL_AGREEMENT_Z *
                           (mean_variance(sums, i, c) + mean_variance(sums, j, c));
            if (d * d > agree)
                continue;
            deviations += squared_deviations(sums, j, c);
            freedom += sums->n[j] - 1.0;
        }
    return deviations / freedom;
}

struct image *pooled_error_image(const struct pixel_sums *sums, int x0, int y0, int x1, int y1,
                                 double confidence)
{
    assert(0 < confidence && confidence < 1);
    double z = normal_critical_two_sided(1.0 - confidence);
    struct image *error = image_create(x1 - x0, y1 - y0);
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            size_t i = (size_t)y * (size_t)sums->width + (size_t)x;
            int n = sums->n[i];
            assert(n >= 2);
            double b[3];
            for (int c = 0; c < 3; c++) {
                double own = squared_deviations(sums, i, c) / (n - 1.0);
                b[c] = z * sqrt(fmax(own, pooled_sample_variance(sums, i, x, y, c)) / n);
            }
            image_set(error, x - x0, y - y0, vec3(b[0], b[1], b[2]));
        }
    return error;
}
