/*
 * modes/pixel_error.c -- a pixel's batches of samples and the error image made from them
 * (pixel_error.h).
 */
#include "pixel_error.h"

#include <assert.h>
#include <math.h>

#include "../base/alloc.h"
#include "../base/normal.h"

int error_batch_size(int count, int n)
{
    int m = 1;
    while (count * m < n)
        m *= 2;
    return m;
}

void error_batches_add(double *batches, int count, int n, const double *v, size_t width)
{
    int m = error_batch_size(count, n + 1);
    if (m > 1 && n == count * (m / 2)) { /* every batch full: pairs become one */
        for (size_t k = 0; k < (size_t)count; k++)
            for (size_t c = 0; c < width; c++)
                batches[width * k + c] = k < (size_t)count / 2
                                             ? batches[2 * width * k + c] +
                                                   batches[2 * width * k + width + c]
                                             : 0.0;
    }
    double *batch = batches + width * (size_t)(n / m);
    for (size_t c = 0; c < width; c++)
        batch[c] += v[c];
}

/* Pixel i's spread in channel c from its k = n / m full batches of m samples: the sum of
 * their means' squared deviations from the mean of those means, times m, so that over
 * k - 1 (*freedom) it estimates the variance of one sample's worth, s^2. */
static double batch_deviations(const struct pixel_sums *sums, size_t i, int c, double *freedom)
{
    int n = sums->n[i], m = error_batch_size(ERROR_BATCHES, n), k = n / m;
    const double *b = sums->batches + (size_t)3 * ERROR_BATCHES * i;
    double mean = 0.0, deviations = 0.0;
    for (int j = 0; j < k; j++)
        mean += b[3 * j + c] / m;
    mean /= k;
    for (int j = 0; j < k; j++) {
        double d = b[3 * j + c] / m - mean;
        deviations += d * d;
    }
    *freedom = k - 1.0;
    return deviations * m;
}

/* Each pixel's spread, computed once for the pools that read it 25 times: per channel
 * its mean over all its samples, its batches' deviations (batch_deviations()) and their
 * degrees of freedom. */
struct spread {
    double mean[3], deviations[3];
    double freedom;
};

/* The variance s^2 / n of pixel p's mean in channel c, by its own batches. */
static double mean_variance(const struct spread *p, int n, int c)
{
    return p->deviations[c] / p->freedom / n;
}

/* The pooled s^2 of channel c over the pixels within ERROR_POOL_RADIUS of pixel i at
 * (x, y), inside the window, whose means agree with i's (pixel_error.h): their batches'
 * deviations over their degrees of freedom. i itself always agrees. */
static double pooled_sample_variance(const struct pixel_sums *sums, const struct spread *spread,
                                     size_t i, int x, int y, int c)
{
    double deviations = 0.0, freedom = 0.0;
    for (int v = y - ERROR_POOL_RADIUS; v <= y + ERROR_POOL_RADIUS; v++)
        for (int u = x - ERROR_POOL_RADIUS; u <= x + ERROR_POOL_RADIUS; u++) {
            if (u < 0 || v < 0 || u >= sums->width || v >= sums->height)
                continue;
            size_t j = (size_t)v * (size_t)sums->width + (size_t)u;
            double d = spread[j].mean[c] - spread[i].mean[c];
            double agree = POOL_AGREEMENT_Z * POOL_AGREEMENT_Z *
                           (mean_variance(&spread[i], sums->n[i], c) +
                            mean_variance(&spread[j], sums->n[j], c));
            if (d * d > agree)
                continue;
            deviations += spread[j].deviations[c];
            freedom += spread[j].freedom;
        }
    return deviations / freedom;
}

struct image *pooled_error_image(const struct pixel_sums *sums, int x0, int y0, int x1, int y1,
                                 double confidence)
{
    assert(0 < confidence && confidence < 1);
    double z = normal_critical_two_sided(1.0 - confidence);
    size_t n_pixels = (size_t)sums->width * (size_t)sums->height;
    struct spread *spread = xcalloc(n_pixels, sizeof *spread, "pixel spreads");
    for (size_t i = 0; i < n_pixels; i++) {
        assert(sums->n[i] >= 2);
        for (int c = 0; c < 3; c++) {
            spread[i].mean[c] = sums->sum[3 * i + c] / sums->n[i];
            spread[i].deviations[c] = batch_deviations(sums, i, c, &spread[i].freedom);
        }
    }
    struct image *error = image_create(x1 - x0, y1 - y0);
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            size_t i = (size_t)y * (size_t)sums->width + (size_t)x;
            int n = sums->n[i];
            double b[3];
            for (int c = 0; c < 3; c++) {
                double own = mean_variance(&spread[i], n, c) * n;
                double pooled = pooled_sample_variance(sums, spread, i, x, y, c);
                b[c] = z * sqrt(fmax(own, pooled) / n);
            }
            image_set(error, x - x0, y - y0, vec3(b[0], b[1], b[2]));
        }
    xfree(spread);
    return error;
}
