/*
 * modes/sppm_error.c -- 2009's error image: the pass values' batches, the bias smoothed
 * over the pixels around, and the bound (sppm_error.h).
 */
#include "sppm_error.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/normal.h"
#include "../image/error_image.h"
#include "pixel_error.h"

#define PIXEL_BATCHES (3 * ERROR_BATCHES) /* the doubles of one pixel's batches */

void kept_window_init(struct kept_window *k, const struct render_settings *asked,
                      int image_width, int image_height, int margin)
{
    k->asked = asked;
    k->grown = *asked;
    k->grown.x0 = asked->x0 > margin ? asked->x0 - margin : 0;
    k->grown.y0 = asked->y0 > margin ? asked->y0 - margin : 0;
    k->grown.x1 = asked->x1 + margin < image_width ? asked->x1 + margin : image_width;
    k->grown.y1 = asked->y1 + margin < image_height ? asked->y1 + margin : image_height;
    k->width = k->grown.x1 - k->grown.x0;
    k->height = k->grown.y1 - k->grown.y0;
    k->out_x0 = asked->x0 - k->grown.x0;
    k->out_y0 = asked->y0 - k->grown.y0;
    k->out_width = asked->x1 - asked->x0;
    k->out_height = asked->y1 - asked->y0;
}

size_t kept_pixel(const struct kept_window *k, size_t written)
{
    size_t x = written % (size_t)k->out_width, y = written / (size_t)k->out_width;
    return (y + (size_t)k->out_y0) * (size_t)k->width + x + (size_t)k->out_x0;
}

size_t written_pixel(const struct kept_window *k, size_t kept)
{
    int x = (int)(kept % (size_t)k->width) - k->out_x0;
    int y = (int)(kept / (size_t)k->width) - k->out_y0;
    if (x < 0 || y < 0 || x >= k->out_width || y >= k->out_height)
        return NOT_WRITTEN;
    return (size_t)y * (size_t)k->out_width + (size_t)x;
}

void sppm_error_create(struct sppm_error *e, const struct kept_window *kept,
                       int block_bias_reach)
{
    size_t n = (size_t)kept->width * (size_t)kept->height;
    e->width = kept->width;
    e->height = kept->height;
    e->x0 = kept->out_x0;
    e->y0 = kept->out_y0;
    e->x1 = kept->out_x0 + kept->out_width;
    e->y1 = kept->out_y0 + kept->out_height;
    e->wx0 = kept->asked->x0;
    e->wy0 = kept->asked->y0;
    e->block_bias_reach = block_bias_reach;
    error_block_grid(e->wx0, e->wy0, e->x1 - e->x0, e->y1 - e->y0, &e->columns, &e->rows);
    e->pass_batches = xcalloc(ERROR_BATCHES * 9 * n, sizeof *e->pass_batches, "sppm batches");
    e->shares = xmalloc(2 * n, sizeof *e->shares, "sppm covered shares");
    for (size_t i = 0; i < 2 * n; i++)
        e->shares[i] = 1.0;
    e->before = xcalloc(n, sizeof *e->before, "sppm pass values");
    e->pass_values = xcalloc(9 * n, sizeof *e->pass_values, "sppm pass values");
    e->pass_scratch = xcalloc(6 * n, sizeof *e->pass_scratch, "sppm pass values");
    e->block_batches = xcalloc(6 * BLOCK_BATCHES * (size_t)e->columns * (size_t)e->rows,
                               sizeof *e->block_batches, "sppm block batches");
}

void sppm_error_add_pass(struct sppm_error *e, size_t i, struct vec3 seen, struct vec3 p,
                         struct vec3 p_inner)
{
    double *v = e->pass_values + 9 * i;
    v[0] = seen.x, v[1] = seen.y, v[2] = seen.z;
    v[3] = p.x, v[4] = p.y, v[5] = p.z;
    v[6] = p_inner.x, v[7] = p_inner.y, v[8] = p_inner.z;
}

/* The batches of the pass values y_i = e_i + P_i / c and of their biases b_i = 2 (y_i -
 * y'_i) = 2 (P_i / c - P'_i / c'), the shares as they stand (sppm_error_add_pass()), or
 * every share 1 when `shared` is 0. */
static void pass_value_batches(const struct sppm_error *e, int shared, double *values,
                               double *biases)
{
    size_t n = (size_t)e->width * (size_t)e->height;
    for (size_t i = 0; i < n; i++) {
        double c = shared ? e->shares[2 * i] : 1.0;
        double c_inner = shared ? e->shares[2 * i + 1] : 1.0;
        for (size_t b = 0; b < ERROR_BATCHES; b++) {
            const double *batch = e->pass_batches + 9 * (n * b + i); /* e, P, P' */
            for (size_t k = 0; k < 3; k++) {
                size_t j = PIXEL_BATCHES * i + 3 * b + k;
                double p = batch[3 + k] / c;
                values[j] = batch[k] + p;
                biases[j] = 2.0 * (p - batch[6 + k] / c_inner);
            }
        }
    }
}

void sppm_error_photons(struct vec3 weight, double radius, struct vec3 tau,
                        struct vec3 inner_tau, double photons_per_pass, struct vec3 *p,
                        struct vec3 *p_inner)
{
    double area = PI * radius * radius;
    *p = vec3_zero();
    *p_inner = vec3_zero();
    if (area * photons_per_pass >= DBL_MIN) {
        double scale = 1.0 / (area * photons_per_pass);
        *p = vec3_scale(vec3_mul(weight, tau), scale);
        *p_inner = vec3_scale(vec3_mul(weight, inner_tau), 2 * scale);
    }
}

/* The sum over the pixels of `line` within SPPM_BIAS_RADIUS of pixel `at` along it (the
 * line's `length` pixels, `step` pixels apart, `stride` doubles each) into sum; returns
 * how many there are. */
static int sum_along(const double *line, int length, size_t step, int at, size_t stride,
                     double *sum)
{
    int from = at > SPPM_BIAS_RADIUS ? at - SPPM_BIAS_RADIUS : 0;
    int to = at + SPPM_BIAS_RADIUS < length ? at + SPPM_BIAS_RADIUS : length - 1;
    memset(sum, 0, stride * sizeof *sum);
    for (int u = from; u <= to; u++)
        for (size_t k = 0; k < stride; k++)
            sum[k] += line[step * stride * (size_t)u + k];
    return to - from + 1;
}

/* Each pixel's b (biases, `stride` doubles a pixel: its batches, or one pass's value)
 * averaged over the pixels within SPPM_BIAS_RADIUS of it, inside the window, into
 * smoothed: the square is a row's pixels times a column's, so the rows are summed first
 * and then their sums down the columns (10 terms a value where the square has 25). */
static void smooth_bias(const struct sppm_error *e, const double *biases, double *smoothed,
                        size_t stride)
{
    size_t width = (size_t)e->width;
    double *rows = xmalloc(stride * width * (size_t)e->height, sizeof *rows, "sppm bias");
    int *members = xmalloc(width, sizeof *members, "sppm bias");
    for (int y = 0; y < e->height; y++)
        for (int x = 0; x < e->width; x++) {
            size_t i = (size_t)y * width + (size_t)x;
            members[x] = sum_along(biases + stride * width * (size_t)y, e->width, 1, x, stride,
                                   rows + stride * i);
        }
    for (int y = 0; y < e->height; y++)
        for (int x = 0; x < e->width; x++) {
            double *out = smoothed + stride * ((size_t)y * width + (size_t)x);
            int in_column =
                sum_along(rows + stride * (size_t)x, e->height, width, y, stride, out);
            for (size_t k = 0; k < stride; k++)
                out[k] /= members[x] * in_column;
        }
    xfree(members);
    xfree(rows);
}

/* The mean of a per-pixel series of the kept window (`stride` doubles a pixel, the first
 * `count` of which are summed into mean) over the pixels of block (column, row) of the
 * written window and those up to `reach` beyond it each side, inside the kept window. */
static void block_mean(const struct sppm_error *e, const double *series, size_t stride,
                       size_t count, int column, int row, int reach, double *mean)
{
    int u0, v0, u1, v1;
    error_block_window(e->wx0, e->wy0, e->x1 - e->x0, e->y1 - e->y0, column, row, &u0, &v0,
                       &u1, &v1);
    u0 = u0 + e->x0 > reach ? u0 + e->x0 - reach : 0; /* now in the kept window */
    v0 = v0 + e->y0 > reach ? v0 + e->y0 - reach : 0;
    u1 = u1 + e->x0 + reach < e->width ? u1 + e->x0 + reach : e->width;
    v1 = v1 + e->y0 + reach < e->height ? v1 + e->y0 + reach : e->height;
    double pixels = (double)(u1 - u0) * (v1 - v0);
    memset(mean, 0, count * sizeof *mean);
    for (int v = v0; v < v1; v++)
        for (int u = u0; u < u1; u++) {
            const double *s = series + stride * ((size_t)v * (size_t)e->width + (size_t)u);
            for (size_t j = 0; j < count; j++)
                mean[j] += s[j] / pixels;
        }
}

/* Block (column, row)'s BLOCK_BATCHES batch sums, 6 each (block_corrected()'s two s). */
static double *block_batches(const struct sppm_error *e, int column, int row)
{
    return e->block_batches + 6 * BLOCK_BATCHES * ((size_t)row * (size_t)e->columns +
                                                   (size_t)column);
}

/* The two values s of block (column, row)'s mean (sppm_error.h), count doubles each (a
 * pass's 3 or a pixel's batches), into s: the mean over the block of the pixels' y less
 * the mean of their b~ over the block grown by its reach, then less their mean over the
 * block alone. */
static void block_corrected(const struct sppm_error *e, const double *y, const double *smoothed,
                            size_t count, int column, int row, double *s)
{
    double bias[PIXEL_BATCHES];
    block_mean(e, y, count, count, column, row, 0, s);
    memcpy(s + count, s, count * sizeof *s);
    block_mean(e, smoothed, count, count, column, row, e->block_bias_reach, bias);
    for (size_t j = 0; j < count; j++)
        s[j] -= bias[j];
    block_mean(e, smoothed, count, count, column, row, 0, bias);
    for (size_t j = 0; j < count; j++)
        s[count + j] -= bias[j];
}

void sppm_error_pass_done(struct sppm_error *e, long pass)
{
    size_t n = (size_t)e->width * (size_t)e->height;
    double *y = e->pass_scratch, *smoothed = e->pass_scratch + 3 * n;
    const double *v = e->pass_values; /* e_i, P_i and P'_i, 3 each */
    error_batches_add(e->pass_batches, ERROR_BATCHES, (int)pass, v, 9 * n);
    for (size_t i = 0; i < n; i++) /* b_i first, into y, to smooth */
        for (int c = 0; c < 3; c++)
            y[3 * i + c] = 2.0 * (v[9 * i + 3 + c] - v[9 * i + 6 + c]);
    smooth_bias(e, y, smoothed, 3);
    for (size_t i = 0; i < n; i++) /* then y_i = e_i + P_i */
        for (int c = 0; c < 3; c++)
            y[3 * i + c] = v[9 * i + c] + v[9 * i + 3 + c];
    for (int row = 0; row < e->rows; row++)
        for (int column = 0; column < e->columns; column++) {
            double s[6];
            block_corrected(e, y, smoothed, 3, column, row, s);
            error_batches_add(block_batches(e, column, row), BLOCK_BATCHES, (int)pass, s, 6);
        }
}

/* Student's t two-sided critical value for `freedom` >= 3 degrees of freedom at the
 * normal's z: the Cornish-Fisher expansion in 1 / freedom (Abramowitz and Stegun
 * 26.7.5, four terms): at z = 1.96, 0.7% below the exact value at 3 and 0.03% at 7. */
static double student_critical(double z, double freedom)
{
    double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2, v = freedom;
    return z + (z3 + z) / (4 * v) + (5 * z5 + 16 * z3 + 3 * z) / (96 * v * v) +
           (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * v * v * v);
}

/* The squared deviations, per channel, of k batches' sums (the first 3 of every `stride`
 * doubles) from their mean. */
static void batch_deviations(const double *batches, size_t stride, int k, double deviations[3])
{
    for (int c = 0; c < 3; c++) {
        double all = 0.0;
        for (int j = 0; j < k; j++)
            all += batches[stride * (size_t)j + (size_t)c] / k;
        deviations[c] = 0.0;
        for (int j = 0; j < k; j++) {
            double d = batches[stride * (size_t)j + (size_t)c] - all;
            deviations[c] += d * d;
        }
    }
}

/* Whether a block keeps its own bias (sppm_error.h): whether d, the luminance of the mean
 * of its b~ over the block less that over its reach, is further from 0 than t times its
 * standard error, from the block's k full batches of m of the n passes (6 doubles each,
 * block_corrected()'s two s, whose difference d is). */
static int keeps_own_bias(const double *batches, int k, int m, int n, double t)
{
    double d[BLOCK_BATCHES], all = 0.0, spread = 0.0;
    for (int j = 0; j < k; j++) {
        const double *s = batches + 6 * j;
        d[j] = vec3_luminance(vec3(s[0] - s[3], s[1] - s[4], s[2] - s[5]));
        all += d[j] / k;
    }
    for (int j = 0; j < k; j++)
        spread += (d[j] - all) * (d[j] - all);
    return fabs(all) / m > t * sqrt(spread / m / (k - 1.0) / n);
}

/* What each block of the written window states (sppm_error.h), into *noise and *bias,
 * by its s and b~ over its reach, or its own where it keeps its own bias. The noise
 * bound: the spread of the block's k full BLOCK_BATCHES batches of m passes of s, every
 * share 1, times the ratio of the spreads of its s from the pixels' batches with the
 * image's shares (shared) and with every share 1 (unshared; 2 PIXEL_BATCHES a block
 * each, block_corrected()), at z_c widened to Student's t for k - 1 degrees of freedom.
 * The bias: the mean of the pixels' b~ (smoothed, PIXEL_BATCHES a pixel). */
static void block_statement(const struct sppm_error *e, const double *shared,
                            const double *unshared, const double *smoothed, long passes,
                            double z, struct image **noise, struct image **bias)
{
    int n = (int)passes, m = error_batch_size(BLOCK_BATCHES, n), k = n / m;
    int pixel_k = n / error_batch_size(ERROR_BATCHES, n);
    double t = student_critical(z, k - 1.0);
    *noise = image_create(e->columns, e->rows);
    *bias = image_create(e->columns, e->rows);
    for (int row = 0; row < e->rows; row++)
        for (int column = 0; column < e->columns; column++) {
            const double *batches = block_batches(e, column, row);
            int own = keeps_own_bias(batches, k, m, n, t);
            size_t block = PIXEL_BATCHES * (2 * ((size_t)row * (size_t)e->columns +
                                                 (size_t)column) + (size_t)own);
            double spread[3], with[3], without[3], bound[3], mean[PIXEL_BATCHES];
            double b[3] = {0.0, 0.0, 0.0};
            batch_deviations(batches + 3 * own, 6, k, spread);
            batch_deviations(shared + block, 3, pixel_k, with);
            batch_deviations(unshared + block, 3, pixel_k, without);
            for (int c = 0; c < 3; c++) {
                double ratio = without[c] > 0.0 ? with[c] / without[c] : 1.0;
                bound[c] = t * sqrt(spread[c] * ratio / m / (k - 1.0) / n);
            }
            image_set(*noise, column, row, vec3(bound[0], bound[1], bound[2]));
            block_mean(e, smoothed, PIXEL_BATCHES, PIXEL_BATCHES, column, row,
                       own ? 0 : e->block_bias_reach, mean);
            for (size_t j = 0; j < PIXEL_BATCHES; j++)
                b[j % 3] += mean[j] / (double)passes;
            image_set(*bias, column, row, vec3(b[0], b[1], b[2]));
        }
}

/* The batches of each pixel's values y into values and of its b~ into smoothed
 * (PIXEL_BATCHES a pixel each), with the shares as they stand or, when `shared` is 0,
 * every share 1; returns each block's two batches of s from them (block_corrected(),
 * 2 PIXEL_BATCHES a block), owned by the caller. */
static double *value_batches(const struct sppm_error *e, int shared, double *values,
                             double *smoothed)
{
    size_t n = (size_t)e->width * (size_t)e->height;
    double *biases = xmalloc(PIXEL_BATCHES * n, sizeof *biases, "sppm bias batches");
    pass_value_batches(e, shared, values, biases);
    smooth_bias(e, biases, smoothed, PIXEL_BATCHES);
    xfree(biases);
    double *blocks = xmalloc(2 * PIXEL_BATCHES * (size_t)e->columns * (size_t)e->rows,
                             sizeof *blocks, "sppm block values");
    for (int row = 0; row < e->rows; row++)
        for (int column = 0; column < e->columns; column++)
            block_corrected(e, values, smoothed, PIXEL_BATCHES, column, row,
                            blocks + 2 * PIXEL_BATCHES * ((size_t)row * (size_t)e->columns +
                                                          (size_t)column));
    return blocks;
}

struct image *sppm_error_image(const struct sppm_error *e, long passes, double confidence,
                               struct image **bias, struct image **block,
                               struct image **block_biases)
{
    size_t n = (size_t)e->width * (size_t)e->height;
    int x0 = e->x0, y0 = e->y0, x1 = e->x1, y1 = e->y1;
    double *smoothed = xmalloc(PIXEL_BATCHES * n, sizeof *smoothed, "sppm bias batches");
    double *corrected = xmalloc(PIXEL_BATCHES * n, sizeof *corrected, "sppm error batches");
    double *sum = xcalloc(3 * n, sizeof *sum, "sppm error sums");
    int *count = xmalloc(n, sizeof *count, "sppm error counts");
    double *unshared = value_batches(e, 0, corrected, smoothed);
    double *shared = value_batches(e, 1, corrected, smoothed);
    for (size_t j = 0; j < PIXEL_BATCHES * n; j++) /* s = y - b~ */
        corrected[j] -= smoothed[j];
    for (size_t i = 0; i < n; i++) { /* the sums of the batches of s */
        count[i] = (int)passes;
        for (size_t k = 0; k < PIXEL_BATCHES; k++)
            sum[3 * i + k % 3] += corrected[PIXEL_BATCHES * i + k];
    }
    struct pixel_sums sums = {e->width, e->height, sum, corrected, count};
    struct image *error = pooled_error_image(&sums, x0, y0, x1, y1, confidence);
    *bias = image_create(x1 - x0, y1 - y0);
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            const double *s = smoothed + PIXEL_BATCHES * ((size_t)y * (size_t)e->width +
                                                          (size_t)x);
            double b[3] = {0.0, 0.0, 0.0};
            for (size_t k = 0; k < PIXEL_BATCHES; k++)
                b[k % 3] += s[k];
            struct vec3 mean = vec3_scale(vec3(b[0], b[1], b[2]), 1.0 / (double)passes);
            struct vec3 bound = image_get(error, x - x0, y - y0);
            image_set(*bias, x - x0, y - y0, mean);
            image_set(error, x - x0, y - y0,
                      vec3_add(bound, vec3(fabs(mean.x), fabs(mean.y), fabs(mean.z))));
        }
    block_statement(e, shared, unshared, smoothed, passes,
                    normal_critical_two_sided(1.0 - confidence), block, block_biases);
    xfree(count);
    xfree(sum);
    xfree(shared);
    xfree(unshared);
    xfree(corrected);
    xfree(smoothed);
    return error;
}

void sppm_error_result(const struct sppm_error *e, const struct kept_window *k, long passes,
                       struct render_result *result)
{
    result->error = sppm_error_image(e, passes, k->grown.error_confidence, &result->bias,
                                     &result->block_noise, &result->block_bias);
}

int sppm_error_target(const struct sppm_error *e, const struct kept_window *k, long passes,
                      const struct image *mean, struct render_counters *counters)
{
    struct render_result r = {NULL, NULL, NULL, NULL, NULL, NULL, 0.0};
    sppm_error_result(e, k, passes, &r);
    struct stated_error stated = {r.error, r.bias, r.block_noise, r.block_bias};
    int reached = target_tally(mean, &stated, k->asked, counters);
    render_result_free(&r);
    return reached;
}

void sppm_error_free(struct sppm_error *e)
{
    xfree(e->pass_batches);
    xfree(e->shares);
    xfree(e->before);
    xfree(e->pass_values);
    xfree(e->pass_scratch);
    xfree(e->block_batches);
    memset(e, 0, sizeof *e);
}
