/*
 * image/error_image.c -- block bounds and the summary of an error image (error_image.h).
 */
#include "error_image.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

#include "../base/alloc.h"
#include "../base/normal.h"

void error_block_grid(int x0, int y0, int width, int height, int *columns, int *rows)
{
    /* the grid's first row and column start at or before the window's top left pixel */
    *columns = (x0 % ERROR_BLOCK + width + ERROR_BLOCK - 1) / ERROR_BLOCK;
    *rows = (y0 % ERROR_BLOCK + height + ERROR_BLOCK - 1) / ERROR_BLOCK;
}

void error_block_window(int x0, int y0, int width, int height, int column, int row, int *u0,
                        int *v0, int *u1, int *v1)
{
    int bx = x0 - x0 % ERROR_BLOCK + column * ERROR_BLOCK;
    int by = y0 - y0 % ERROR_BLOCK + row * ERROR_BLOCK;
    *u0 = bx > x0 ? bx - x0 : 0;
    *v0 = by > y0 ? by - y0 : 0;
    *u1 = bx + ERROR_BLOCK - x0 < width ? bx + ERROR_BLOCK - x0 : width;
    *v1 = by + ERROR_BLOCK - y0 < height ? by + ERROR_BLOCK - y0 : height;
}

/* Pixel (x, y)'s estimated bias b (signed, per channel) and its bound's noise part
 * B - |b|: b = 0 without a bias image. */
static void bound_parts(const struct stated_error *stated, int x, int y, struct vec3 *b,
                        struct vec3 *noise)
{
    *b = stated->bias != NULL ? image_get(stated->bias, x, y) : vec3_zero();
    struct vec3 bound = image_get(stated->error, x, y);
    *noise = vec3(bound.x - fabs(b->x), bound.y - fabs(b->y), bound.z - fabs(b->z));
}

/* What block (column, row)'s bound is made of, summed over its pixels [u0, u1) x [v0, v1):
 * the image's luminance, the bias b per channel and in luminance (the mode's block_bias
 * n times, where it states one), and the squares of the pixels' noise parts per channel
 * and in luminance (error_image.h). */
struct block_sums {
    double n, luminance, bias_luminance, noise2_luminance;
    struct vec3 bias, noise2;
};

static struct block_sums block_sums(const struct image *image, const struct stated_error *stated,
                                    int column, int row, int u0, int v0, int u1, int v1)
{
    struct block_sums s = {0.0, 0.0, 0.0, 0.0, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    for (int y = v0; y < v1; y++)
        for (int x = u0; x < u1; x++) {
            struct vec3 b, noise;
            bound_parts(stated, x, y, &b, &noise);
            double l = vec3_luminance(noise);
            s.luminance += vec3_luminance(image_get(image, x, y));
            s.bias = vec3_add(s.bias, b);
            s.bias_luminance += vec3_luminance(b);
            s.noise2 = vec3_add(s.noise2, vec3_mul(noise, noise));
            s.noise2_luminance += l * l;
        }
    s.n = (double)(u1 - u0) * (double)(v1 - v0);
    if (stated->block_bias != NULL) { /* the mode's own, as if each pixel had it */
        s.bias = vec3_scale(image_get(stated->block_bias, column, row), s.n);
        s.bias_luminance = vec3_luminance(s.bias);
    }
    return s;
}

/* The mean luminance of image over block (column, row)'s pixels [u0, u1) x [v0, v1) and
 * the bound on it (error_image.h). */
static void block_bound(const struct image *image, const struct stated_error *stated,
                        int column, int row, int u0, int v0, int u1, int v1, double *mean,
                        double *bound)
{
    struct block_sums s = block_sums(image, stated, column, row, u0, v0, u1, v1);
    double noise = stated->block_noise != NULL
                       ? vec3_luminance(image_get(stated->block_noise, column, row))
                       : sqrt(s.noise2_luminance) / s.n;
    *mean = s.luminance / s.n;
    *bound = fabs(s.bias_luminance) / s.n + noise;
}

struct image *block_error_image(const struct image *image, const struct stated_error *stated,
                                int x0, int y0)
{
    int columns, rows;
    error_block_grid(x0, y0, image->width, image->height, &columns, &rows);
    struct image *blocks = image_create(columns, rows);
    for (int row = 0; row < rows; row++)
        for (int column = 0; column < columns; column++) {
            int u0, v0, u1, v1;
            error_block_window(x0, y0, image->width, image->height, column, row, &u0, &v0,
                               &u1, &v1);
            struct block_sums s = block_sums(image, stated, column, row, u0, v0, u1, v1);
            struct vec3 noise = stated->block_noise != NULL
                                    ? image_get(stated->block_noise, column, row)
                                    : vec3_scale(vec3(sqrt(s.noise2.x), sqrt(s.noise2.y),
                                                      sqrt(s.noise2.z)), 1.0 / s.n);
            struct vec3 bias = vec3_scale(s.bias, 1.0 / s.n);
            image_set(blocks, column, row,
                      vec3_add(vec3(fabs(bias.x), fabs(bias.y), fabs(bias.z)), noise));
        }
    return blocks;
}

struct block_count blocks_within(const struct image *image, const struct stated_error *stated,
                                 int x0, int y0, double e)
{
    assert(image->width == stated->error->width && image->height == stated->error->height);
    struct block_count count = {0, 0, -1, -1};
    int columns, rows;
    error_block_grid(x0, y0, image->width, image->height, &columns, &rows);
    assert(stated->block_noise == NULL || (stated->block_noise->width == columns &&
                                           stated->block_noise->height == rows));
    for (int row = 0; row < rows; row++)
        for (int column = 0; column < columns; column++) {
            int u0, v0, u1, v1;
            error_block_window(x0, y0, image->width, image->height, column, row, &u0, &v0,
                               &u1, &v1);
            double mean, bound;
            block_bound(image, stated, column, row, u0, v0, u1, v1, &mean, &bound);
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

/* The luminance standard error of a pixel whose channels' means have variances var:
 * sum_c w_c sqrt(var_c), its channels being one estimate's. */
static double luminance_sigma(struct vec3 var)
{
    return vec3_luminance(vec3(sqrt(var.x), sqrt(var.y), sqrt(var.z)));
}

/* Block [x0, x1) x [y0, y1): the means of a's and b's luminance and the standard errors
 * of those means by var_a and var_b (NULL: 0), pixels independent. */
static void block_means(const struct image *a, const struct image *var_a,
                        const struct image *b, const struct image *var_b, int x0, int y0,
                        int x1, int y1, double out[4])
{
    double sa = 0.0, sb = 0.0, va = 0.0, vb = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            double ea = var_a != NULL ? luminance_sigma(image_get(var_a, x, y)) : 0.0;
            double eb = var_b != NULL ? luminance_sigma(image_get(var_b, x, y)) : 0.0;
            sa += vec3_luminance(image_get(a, x, y));
            sb += vec3_luminance(image_get(b, x, y));
            va += ea * ea;
            vb += eb * eb;
        }
    double n = (double)(x1 - x0) * (double)(y1 - y0);
    out[0] = sa / n;
    out[1] = sb / n;
    out[2] = sqrt(va) / n;
    out[3] = sqrt(vb) / n;
}

static int by_value(const void *p, const void *q)
{
    double x = *(const double *)p, y = *(const double *)q;
    return (x > y) - (x < y);
}

struct bound_check bound_check(const struct image *a, const struct image *var_a,
                               const struct image *b, const struct image *var_b, double z)
{
    struct bound_check check = {0, 0, 0.0, 0.0};
    int columns = (a->width + ERROR_BLOCK - 1) / ERROR_BLOCK;
    int rows = (a->height + ERROR_BLOCK - 1) / ERROR_BLOCK;
    double *ratio = xcalloc((size_t)columns * (size_t)rows, sizeof *ratio, "block ratios");
    double bound2 = 0.0, error2 = 0.0;
    int n_ratios = 0;
    for (int y0 = 0; y0 < a->height; y0 += ERROR_BLOCK)
        for (int x0 = 0; x0 < a->width; x0 += ERROR_BLOCK) {
            double m[4];
            int x1 = x0 + ERROR_BLOCK < a->width ? x0 + ERROR_BLOCK : a->width;
            int y1 = y0 + ERROR_BLOCK < a->height ? y0 + ERROR_BLOCK : a->height;
            block_means(a, var_a, b, var_b, x0, y0, x1, y1, m);
            if (m[1] < ERROR_DARK_FLOOR)
                continue;
            double d = fabs(m[0] - m[1]), bound = z * m[2];
            check.n_blocks++;
            check.covered += d <= sqrt(bound * bound + z * m[3] * z * m[3]);
            if (d > 0 || bound > 0) /* else exact, and stated so: no ratio to take */
                ratio[n_ratios++] = d > 0 ? bound / d : HUGE_VAL;
            bound2 += bound * bound;
            error2 += d * d;
        }
    check.median_ratio = -1.0;
    check.rms_ratio = -1.0;
    if (n_ratios > 0) {
        qsort(ratio, (size_t)n_ratios, sizeof *ratio, by_value);
        check.median_ratio = ratio[n_ratios / 2];
        check.rms_ratio = error2 > 0 ? sqrt(bound2 / error2) : HUGE_VAL;
    }
    xfree(ratio);
    return check;
}

struct error_summary error_summary(const struct image *image, const struct stated_error *stated,
                                   double confidence, int x0, int y0)
{
    struct error_summary s = {0.0, 0, 0, 0};
    double z = normal_critical_two_sided(1.0 - confidence);
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++) {
            struct vec3 b, noise;
            bound_parts(stated, x, y, &b, &noise);
            for (int c = 0; c < 3; c++) {
                double sigma = vec3_get(noise, c) / z, v = vec3_get(image_get(image, x, y), c);
                s.relmse += (vec3_get(b, c) * vec3_get(b, c) + sigma * sigma) / (v * v + 1e-2);
            }
        }
    s.relmse /= 3.0 * (double)image->width * (double)image->height;
    struct block_count one = blocks_within(image, stated, x0, y0, 0.01);
    struct block_count three = blocks_within(image, stated, x0, y0, 0.03);
    s.n_blocks = one.n_blocks;
    s.within_1 = one.within;
    s.within_3 = three.within;
    return s;
}
