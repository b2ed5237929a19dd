/*
 * image/compare.c -- error metrics of a test image a against a reference b, the block test
 * of their agreement, and the `photon compare` command that prints them.
 *
 * The metrics (compare.h's struct image_error) sum over all 3 * width * height channel
 * values in index order; relmse's 1e-2 keeps black reference pixels from dominating, and
 * divisions safe. Infinities are printed "inf" by us (printf's spelling is
 * implementation-defined); "psnr=none" when b has no positive value and mse > 0.
 *
 * The block test (image_block_test), the verdict. A variance image holds per pixel and
 * channel the variance of the pixel's estimate (of the mean, not of one sample); an error
 * image a bound B at confidence C, read as the standard error B / z_{(1+C)/2}. In each
 * size x size block (default 16) and channel, over its n pixels, pixels independent:
 *   d = mean(a) - mean(b),  var = (sum var_a + sum var_b) / n^2,  z = d / sqrt(var),
 * computed as sum(a - b) / sqrt(sum var_a + sum var_b). A block mean of thousands of
 * samples is far closer to normal than a pixel, and a sum of n per-pixel variances far
 * less noisy than one (from a few heavy-tailed samples, mostly too small: the old
 * per-pixel test cried wolf). Each of m = 3 * blocks_tested values is tested two-sided at
 * the Sidak level 1 - (1 - alpha)^(1/m); consistent when none fails. A block's channels
 * are correlated (the same paths); Sidak's inequality holds for two-sided tests of jointly
 * normal values of any correlation, so false alarms stay at most alpha. Per channel, not
 * luminance: an error of one colour is not diluted (blue weighs 0.0722 in luminance), and
 * a channel's variance is what the image holds, where luminance's needs the channels'
 * covariance. Normal, not Student's t or an inflation: a variance image has no sample
 * counts, and measured on independent pt renders of scenes/cornell.scene (16 x 16 blocks)
 * z is narrower than normal (mean z^2 0.55 at 32 x 32 and 16 samples, where stratified
 * samples' variance is over-estimated; 0.83 and 0.79 at 64 x 64 and 16 or 64) with a tail
 * no heavier at Sidak's levels (P(|z| > 3.29) 0.00104 and 0.00073, normal 0.00100), and
 * whole-image false alarms 1 in 1000, 300 and 200 pairs at alpha 0.01. Where var = 0 the
 * difference must be exactly 0 (|z| 0, else +Inf); a block with a pixel of variance +Inf
 * (an error image's "cannot bound") is untestable: counted, not tested.
 *
 * `photon compare` prints one line on stdout: rmse=%.6g relmse=%.6g psnr=%.4f
 * maxerr=%.6g, then --block's figures (worst_block=%.6g ... mean_ratio=%.6g) and the block
 * test's fields, each documented in compare_help (photon compare --help) and the README;
 * on bad input a message on stderr, nothing on stdout, and status 2.
 * Options are parsed into struct compare_args: a new option is a field and a table entry.
 */
#include "compare.h"

#include "../base/input.h"
#include "../base/number.h"
#include "../base/option_once.h"
#include "../base/output.h"
#include "error_image.h"
#include "diff_picture.h"

#include <assert.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define RELMSE_EPSILON 1e-2 /* compare.h's definition of relmse */
/* The usage in four parts: one line in a message, four in --help (within 100 columns). */
#define COMPARE_USAGE_1 "usage: photon compare A.pfm B.pfm [--diff OUT.png|.ppm [--diff-absolute]]"
#define COMPARE_USAGE_2 "[--ref-variance VB.pfm | --ref-error EB.pfm | --ref-block-error BB.pfm]"
#define COMPARE_USAGE_3 "[--test-variance VA.pfm | --test-error EA.pfm | --test-block-error BA.pfm]"
#define COMPARE_USAGE_4 "[--confidence C] [--alpha ALPHA] [--block N] [--exit-status]"
#define COMPARE_USAGE COMPARE_USAGE_1 " " COMPARE_USAGE_2 " " COMPARE_USAGE_3 " " COMPARE_USAGE_4
#define COMPARE_INDENT "\n                      " /* under "A.pfm" */
#define DEFAULT_ALPHA 0.01      /* family-wise level of the test when --alpha is not given */
#define DEFAULT_CONFIDENCE 0.95 /* an error image's confidence when --confidence is not given */
#define DEFAULT_TEST_BLOCK 16   /* the block test's side when --block is not given */
#define EXIT_INCONSISTENT 1     /* --exit-status: like diff(1), 1 for "they differ" */
#define EXIT_TROUBLE 2          /* and 2 for bad input, or no verdict */
/* Documented limit: the smallest --alpha. Sidak's per-channel level alpha / (3 pixels)
 * stays a positive double down to here for every image size (3 x 2^30 channels at most
 * give 3e-310), as normal_critical_two_sided() needs; a smaller level would round to 0. */
#define ALPHA_MIN 1e-300

struct image_error image_compare(const struct image *a, const struct image *b)
{
    assert(a->width == b->width && a->height == b->height);
    size_t n_pixels = (size_t)a->width * (size_t)a->height;
    double sum2 = 0, sum_rel = 0, peak = 0, maxerr = 0;
    for (size_t i = 0; i < n_pixels; i++) {
        for (int c = 0; c < 3; c++) {
            double bc = vec3_get(b->pixels[i], c);
            double d = vec3_get(a->pixels[i], c) - bc;
            sum2 += d * d;
            sum_rel += d * d / (bc * bc + RELMSE_EPSILON); /* denominator >= 1e-2 */
            peak = fmax(peak, bc);
            maxerr = fmax(maxerr, fabs(d));
        }
    }
    double n = 3.0 * (double)n_pixels; /* >= 3: an image is at least 1x1 */
    double mse = sum2 / n;
    struct image_error e;
    e.rmse = sqrt(mse);
    e.relmse = sum_rel / n;
    e.has_psnr = mse == 0 || peak > 0;
    e.psnr = mse == 0 ? HUGE_VAL : peak > 0 ? 10.0 * log10(peak * peak / mse) : 0;
    e.maxerr = maxerr;
    return e;
}

/* The variance of pixel i's channel c in var; NULL: an exact image. */
static double variance_at(const struct image *var, size_t i, int c)
{
    return var != NULL ? vec3_get(var->pixels[i], c) : 0.0;
}

/* One block's test, from the sums of a - b, b and var_a + var_b over its pixels in row
 * order: whether a variance is +Inf, the channel of the largest |z|, that |z|, and that
 * channel's sum(a - b) / sum(b), signed. */
struct block_z {
    int untestable, channel;
    double z, relative;
};

static struct block_z block_z(const struct image *a, const struct image *b,
                              const struct image *var_a, const struct image *var_b, int x0,
                              int y0, int size)
{
    int x1 = x0 + size < a->width ? x0 + size : a->width;
    int y1 = y0 + size < a->height ? y0 + size : a->height;
    double d[3] = {0, 0, 0}, sum_b[3] = {0, 0, 0}, var[3] = {0, 0, 0};
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            size_t i = (size_t)y * (size_t)a->width + (size_t)x;
            for (int c = 0; c < 3; c++) {
                double bc = vec3_get(b->pixels[i], c);
                d[c] += vec3_get(a->pixels[i], c) - bc;
                sum_b[c] += bc;
                var[c] += variance_at(var_a, i, c) + variance_at(var_b, i, c);
            }
        }
    struct block_z r = {0, 0, 0.0, 0.0};
    for (int c = 0; c < 3; c++) {
        r.untestable |= isinf(var[c]);
        double z = var[c] > 0 ? fabs(d[c]) / sqrt(var[c]) : (d[c] != 0 ? HUGE_VAL : 0.0);
        if (c == 0 || z > r.z) {
            r.z = z;
            r.channel = c;
            r.relative = d[c] == 0 ? 0.0 : sum_b[c] != 0 ? d[c] / sum_b[c]
                                                          : copysign(HUGE_VAL, d[c]);
        }
    }
    return r;
}

struct block_verdict image_block_test(const struct image *a, const struct image *b,
                                      const struct image *var_a, const struct image *var_b,
                                      int size, double alpha)
{
    assert(a->width == b->width && a->height == b->height);
    assert(size >= 1 && alpha > 0 && alpha < 1);
    struct block_verdict v;
    memset(&v, 0, sizeof v);
    v.alpha = alpha;
    v.size = size;
    v.worst_channel = -1;
    for (int y0 = 0; y0 < a->height; y0 += size) /* pass 1: counts and the worst block */
        for (int x0 = 0; x0 < a->width; x0 += size) {
            struct block_z r = block_z(a, b, var_a, var_b, x0, y0, size);
            v.n_untestable += r.untestable;
            v.n_tested += !r.untestable;
            if (!r.untestable && (v.worst_channel < 0 || r.z > v.worst_z)) {
                v.worst_z = r.z;
                v.worst_x0 = x0;
                v.worst_y0 = y0;
                v.worst_channel = r.channel;
                v.worst_relative = r.relative;
            }
        }
    v.consistent = v.n_tested > 0 ? 1 : -1;
    if (v.n_tested == 0)
        return v;
    /* Sidak as -expm1(log1p(-alpha) / m), so that a tiny level keeps its digits */
    v.alpha_one = -expm1(log1p(-alpha) / (3.0 * (double)v.n_tested));
    v.z_critical = normal_critical_two_sided(v.alpha_one);
    if (v.worst_z < v.z_critical)
        return v; /* no block fails: pass 2 would find none */
    v.consistent = 0;
    for (int y0 = 0; y0 < a->height; y0 += size) /* pass 2: the failed blocks */
        for (int x0 = 0; x0 < a->width; x0 += size) {
            struct block_z r = block_z(a, b, var_a, var_b, x0, y0, size);
            if (r.untestable || r.z < v.z_critical)
                continue;
            if (v.n_failed < BLOCK_TEST_LISTED) {
                v.failed_x0[v.n_failed] = x0;
                v.failed_y0[v.n_failed] = y0;
            }
            v.n_failed++;
        }
    return v;
}

/* The per-pixel test is the block test with blocks of one pixel: z = (a - b) /
 * sqrt(var_a + var_b) per pixel and channel at the Sidak level of m = 3 * width * height. */
struct consistency image_consistency(const struct image *a, const struct image *b,
                                     const struct image *var_a, const struct image *var_b,
                                     double alpha)
{
    struct block_verdict v = image_block_test(a, b, var_a, var_b, 1, alpha);
    size_t n = (size_t)a->width * (size_t)a->height, failed = (size_t)v.n_failed;
    struct consistency s = {alpha, v.alpha_one, v.z_critical, n, failed,
                            (double)(n - failed) / (double)n, failed == 0,
                            (size_t)v.worst_y0 * (size_t)a->width + (size_t)v.worst_x0,
                            v.worst_z};
    return s;
}

/* img (owned; NULL: already refused) when it has like's size and no value below 0 (nor
 * NaN); else NULL with *err filled, img freed. what: "variance" or "bound". */
static struct image *checked_like(struct image *img, const char *name, const struct image *like,
                                  const char *what, struct error *err)
{
    long long k = -1, n = img != NULL ? 3LL * img->width * img->height : 0;
    while (++k < n && vec3_get(img->pixels[k / 3], (int)(k % 3)) >= 0)
        ; /* k: the first value (row order, then channel) that is not >= 0, or n */
    if (img != NULL && (img->width != like->width || img->height != like->height)) {
        error_set(err, name, 0, "%s image is %dx%d, but the images compared %s %dx%d",
                  what, img->width, img->height,
                  like->pixels == NULL ? "have blocks of 16 x 16 pixels" : "are", like->width,
                  like->height);
    } else if (k < n) {
        double value = vec3_get(img->pixels[k / 3], (int)(k % 3));
        error_set(err, name, 0, "pixel (%lld, %lld) from the top left has a %s %s (%g) in "
                  "channel %lld; %ss must be >= 0%s", k / 3 % img->width, k / 3 / img->width,
                  isnan(value) ? "NaN" : "negative", what, value, k % 3, what,
                  strcmp(what, "bound") == 0 ? " or +Inf" : "");
    } else {
        return img;
    }
    image_free(img);
    return NULL;
}

struct image *variance_read(const char *name, const struct image *like, struct error *err)
{
    return checked_like(image_read(name, err), name, like, "variance", err); /* no NaN, Inf */
}

struct image *error_image_read(const char *name, const struct image *like, double confidence,
                               struct error *err)
{
    assert(confidence > 0 && 1.0 - confidence > 0 && 1.0 - confidence < 1);
    struct image *e = checked_like(image_read_bounds(name, err), name, like, "bound", err);
    double z = normal_critical_two_sided(1.0 - confidence);
    size_t n_pixels = e != NULL ? (size_t)e->width * (size_t)e->height : 0;
    for (size_t i = 0; i < n_pixels; i++) {
        struct vec3 b = e->pixels[i];
        double sx = b.x / z, sy = b.y / z, sz = b.z / z; /* +Inf stays +Inf */
        e->pixels[i] = vec3(sx * sx, sy * sy, sz * sz);
    }
    return e;
}

struct image *block_error_read(const char *name, const struct image *like, double confidence,
                               struct error *err)
{
    assert(confidence > 0 && 1.0 - confidence > 0 && 1.0 - confidence < 1);
    int columns, rows;
    error_block_grid(0, 0, like->width, like->height, &columns, &rows);
    struct image grid = {columns, rows, NULL};
    struct image *blocks = checked_like(image_read_bounds(name, err), name, &grid, "bound", err);
    if (blocks == NULL)
        return NULL;
    struct image *var = image_create(like->width, like->height);
    double z = normal_critical_two_sided(1.0 - confidence);
    for (int row = 0; row < rows; row++)
        for (int column = 0; column < columns; column++) {
            int u0, v0, u1, v1;
            error_block_window(0, 0, like->width, like->height, column, row, &u0, &v0, &u1,
                               &v1);
            double n = (double)(u1 - u0) * (double)(v1 - v0);
            struct vec3 b = vec3_scale(image_get(blocks, column, row), 1.0 / z);
            struct vec3 pixel = vec3_scale(vec3_mul(b, b), n); /* +Inf stays +Inf */
            for (int y = v0; y < v1; y++)
                for (int x = u0; x < u1; x++)
                    image_set(var, x, y, pixel);
        }
    image_free(blocks);
    return var;
}

/* What `photon compare` was asked to do. */
struct compare_args {
    const char *test, *reference; /* A.pfm, the image judged, and B.pfm, its reference    */
    const char *diff;             /* --diff OUT.png or .ppm, or NULL                       */
    int diff_absolute;            /* --diff-absolute: --diff shows |a - b|, not relative    */
    const char *ref_variance, *test_variance; /* --ref-variance VB.pfm, --test-variance VA */
    const char *ref_error, *test_error;       /* --ref-error EB.pfm, --test-error EA.pfm   */
    const char *ref_blocks, *test_blocks;     /* --ref-block-error, --test-block-error     */
    const char *alpha_text, *confidence_text, *block_text; /* as given, or NULL           */
    double alpha, confidence; /* the test's level and the error images' confidence       */
    int block;                /* > 0: report the worst block of this size                */
    int exit_status;          /* --exit-status: the verdict in the exit status           */
};

/* Mean luminance of the pixels of image in [x0, x1) x [y0, y1). */
static double block_mean(const struct image *image, int x0, int y0, int x1, int y1)
{
    double sum = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            sum += vec3_luminance(image_get(image, x, y));
    return sum / ((double)(x1 - x0) * (double)(y1 - y0));
}

int block_is_noisy(const struct image *b, const struct image *var_b, int x0, int y0,
                   int size)
{
    if (var_b == NULL)
        return 0;
    int x1 = x0 + size < b->width ? x0 + size : b->width;
    int y1 = y0 + size < b->height ? y0 + size : b->height;
    double variance = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            struct vec3 v = image_get(var_b, x, y);
            double sd = vec3_luminance(vec3(sqrt(v.x), sqrt(v.y), sqrt(v.z)));
            variance += sd * sd;
        }
    double n = (double)(x1 - x0) * (double)(y1 - y0);
    return sqrt(variance) / n > BLOCK_NOISE_FLOOR * fabs(block_mean(b, x0, y0, x1, y1));
}

struct block_error image_worst_block(const struct image *a, const struct image *b,
                                     const struct image *var_b, int size)
{
    struct block_error worst = {0, 0, 0.0, 0, 0, 0};
    for (int y0 = 0; y0 < a->height; y0 += size)
        for (int x0 = 0; x0 < a->width; x0 += size) {
            if (block_is_noisy(b, var_b, x0, y0, size)) {
                worst.n_noisy++;
                continue;
            }
            int x1 = x0 + size < a->width ? x0 + size : a->width;
            int y1 = y0 + size < a->height ? y0 + size : a->height;
            double mean_a = block_mean(a, x0, y0, x1, y1), mean_b = block_mean(b, x0, y0, x1, y1);
            double relative = mean_a == mean_b ? 0.0
                              : mean_b != 0.0  ? fabs(mean_a - mean_b) / fabs(mean_b)
                                               : INFINITY;
            worst.n_blocks++;
            worst.n_within += relative <= BLOCK_TOLERANCE;
            if (relative > worst.relative_error) {
                worst.x0 = x0;
                worst.y0 = y0;
                worst.relative_error = relative;
            }
        }
    return worst;
}

const struct option_arity compare_options[] = {
    {"--diff", 1},          {"--diff-absolute", 0},   {"--ref-variance", 1},
    {"--test-variance", 1}, {"--ref-error", 1},       {"--test-error", 1},
    {"--ref-block-error", 1}, {"--test-block-error", 1}, {"--confidence", 1},
    {"--alpha", 1},         {"--block", 1},           {"--exit-status", 0},
    {"--help", 0},          {NULL, 0},
};

/* The field an option's value goes to, or NULL when arg is not an option with a value. */
static const char **option_value(struct compare_args *args, const char *arg)
{
    const char *names[] = {"--diff", "--ref-variance", "--test-variance", "--ref-error",
                           "--test-error", "--ref-block-error", "--test-block-error",
                           "--alpha", "--confidence", "--block"};
    const char **fields[] = {&args->diff, &args->ref_variance, &args->test_variance,
                             &args->ref_error, &args->test_error, &args->ref_blocks,
                             &args->test_blocks, &args->alpha_text, &args->confidence_text,
                             &args->block_text};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (strcmp(arg, names[k]) == 0)
            return fields[k];
    return NULL;
}

/* --alpha and --confidence: numbers strictly between 0 and 1, --alpha from ALPHA_MIN (and
 * both meaningful only with what they apply to); --block: a whole number, 1 to 65536; a
 * side given twice; --exit-status without a test. */
static int check_test_args(struct compare_args *args, struct error *err)
{
    int tested = args->ref_variance || args->test_variance || args->ref_error ||
                 args->test_error || args->ref_blocks || args->test_blocks;
    int bounds = args->ref_error || args->test_error || args->ref_blocks || args->test_blocks;
    double size = DEFAULT_TEST_BLOCK;
    args->alpha = DEFAULT_ALPHA;
    args->confidence = DEFAULT_CONFIDENCE;
    if (!!args->ref_variance + !!args->ref_error + !!args->ref_blocks > 1 ||
        !!args->test_variance + !!args->test_error + !!args->test_blocks > 1)
        return error_set(err, "", 0, "compare: a side takes one of a variance image, an "
                                     "error image and a block statement; " COMPARE_USAGE);
    if ((args->alpha_text || args->exit_status) && !tested)
        return error_set(err, "", 0, "compare: %s needs --ref-variance, --ref-error, "
                         "--test-variance or --test-error; " COMPARE_USAGE,
                         args->alpha_text ? "--alpha" : "--exit-status");
    if (args->confidence_text && !bounds)
        return error_set(err, "", 0, "compare: --confidence needs an error image or a block "
                                     "statement; " COMPARE_USAGE);
    if (args->alpha_text && (!number_parse(args->alpha_text, 0, &args->alpha) ||
                             !(args->alpha >= ALPHA_MIN && args->alpha < 1)))
        return error_set(err, "", 0, "compare: --alpha '%s' must be a number from %g up to "
                         "1 (exclusive), such as 0.01", args->alpha_text, ALPHA_MIN);
    if (args->confidence_text && (!number_parse(args->confidence_text, 0, &args->confidence)
                                  || !(args->confidence > 0 && 1.0 - args->confidence > 0 &&
                                       1.0 - args->confidence < 1)))
        return error_set(err, "", 0, "compare: --confidence '%s' must be a number above 0 "
                         "and below 1, such as 0.95", args->confidence_text);
    if (args->block_text && (!number_parse(args->block_text, 1, &size) || size < 1 ||
                             size > 65536))
        return error_set(err, "", 0, "compare: --block '%s' must be a whole number of pixels "
                         "from 1 to 65536; " COMPARE_USAGE, args->block_text);
    args->block = (int)size;
    if ((args->ref_blocks || args->test_blocks) && args->block != ERROR_BLOCK)
        return error_set(err, "", 0, "compare: --block %d: a block statement is of blocks "
                         "of %d x %d pixels, the test's with it", args->block, ERROR_BLOCK,
                         ERROR_BLOCK);
    return 0;
}

static int parse_compare_args(int argc, char **argv, struct compare_args *args,
                              struct error *err)
{
    const char *files[2] = {NULL, NULL};
    int n_files = 0;
    struct option_once once = {{0}, 0};
    memset(args, 0, sizeof *args);
    for (int i = 1; i < argc; i++) {
        const char **value = option_value(args, argv[i]);
        if (value != NULL) {
            if (i + 1 == argc)
                return error_set(err, "", 0, "compare: %s needs a %s; " COMPARE_USAGE,
                                 argv[i], value == &args->alpha_text ||
                                 value == &args->block_text ||
                                 value == &args->confidence_text ? "number" : "file name");
            if (option_once(&once, "compare", argc, argv, i, 1, err) < 0)
                return -1;
            *value = argv[++i];
        } else if (strcmp(argv[i], "--exit-status") == 0) {
            args->exit_status = 1;
        } else if (strcmp(argv[i], "--diff-absolute") == 0) {
            args->diff_absolute = 1;
        } else if (argv[i][0] == '-') {
            return error_set(err, "", 0, "compare: unknown option '%s'; " COMPARE_USAGE,
                             argv[i]);
        } else if (n_files < 2) {
            files[n_files++] = argv[i];
        } else {
            return error_set(err, "", 0, "compare: more than two images; " COMPARE_USAGE);
        }
    }
    if (n_files != 2)
        return error_set(err, "", 0, "compare: expected two images; " COMPARE_USAGE);
    args->test = files[0];
    args->reference = files[1];
    size_t n = args->diff != NULL ? strlen(args->diff) : 0;
    if (args->diff != NULL && (n < 5 || (strcmp(args->diff + n - 4, ".png") != 0 &&
                                         strcmp(args->diff + n - 4, ".ppm") != 0)))
        return error_set(err, "", 0, "compare: --diff '%s': expected a file name ending in "
                         ".png or .ppm", args->diff);
    if (args->diff_absolute && args->diff == NULL)
        return error_set(err, "", 0, "compare: --diff-absolute needs --diff OUT.png; "
                         COMPARE_USAGE);
    return check_test_args(args, err);
}

/* The metrics, without the line's end (the test's fields may follow). */
static void print_metrics(const struct image_error *e)
{
    printf("rmse=%.6g relmse=%.6g ", e->rmse, e->relmse);
    if (!e->has_psnr)
        printf("psnr=none");
    else if (isinf(e->psnr))
        printf("psnr=inf");
    else
        printf("psnr=%.4f", e->psnr);
    printf(" maxerr=%.6g", e->maxerr);
}

/* The images compare_files works on; each owned, NULL when not (yet) read. */
struct compare_inputs {
    struct image *a, *b;         /* test and reference                                  */
    struct image *var_a, *var_b; /* their variances (from error images too), when given */
};

/* A side's variance image: from a variance image, an error image, a block statement, or
 * none (NULL, no error). -1 with *err filled. */
static int read_variance(const char *variance, const char *error, const char *blocks,
                         const struct image *like, double confidence, struct image **var,
                         struct error *err)
{
    if (variance != NULL)
        *var = variance_read(variance, like, err);
    else if (error != NULL)
        *var = error_image_read(error, like, confidence, err);
    else if (blocks != NULL)
        *var = block_error_read(blocks, like, confidence, err);
    return (variance != NULL || error != NULL || blocks != NULL) && *var == NULL ? -1 : 0;
}

/* Reads every input named in args and checks their sizes; -1 with *err filled, leaving
 * what was read in *in for the caller to free. */
static int read_inputs(const struct compare_args *args, struct compare_inputs *in,
                       struct error *err)
{
    in->a = image_read(args->test, err);
    if (in->a == NULL)
        return error_set(err, err->file, err->line, "%s (A, the image tested)", err->message);
    in->b = image_read(args->reference, err);
    if (in->b == NULL)
        return error_set(err, err->file, err->line, "%s (B, the reference)", err->message);
    if (in->a->width != in->b->width || in->a->height != in->b->height)
        return error_set(err, args->test, 0, "size %dx%d differs from %s: %dx%d",
                         in->a->width, in->a->height, args->reference, in->b->width,
                         in->b->height);
    if (read_variance(args->test_variance, args->test_error, args->test_blocks, in->a,
                      args->confidence, &in->var_a, err) < 0)
        return -1;
    return read_variance(args->ref_variance, args->ref_error, args->ref_blocks, in->a,
                         args->confidence, &in->var_b, err);
}

/* blocks_noisy=N and noisy_blocks=X,Y;X,Y;... (or "none"): the blocks of reference b
 * below its noise floor, which the block figures leave out. */
static void print_noisy_blocks(const struct image *b, const struct image *var_b, int size,
                               int n_noisy)
{
    printf(" blocks_noisy=%d noisy_blocks=", n_noisy);
    const char *separator = "";
    for (int y0 = 0; y0 < b->height; y0 += size)
        for (int x0 = 0; x0 < b->width; x0 += size)
            if (block_is_noisy(b, var_b, x0, y0, size)) {
                printf("%s%d,%d", separator, x0, y0);
                separator = ";";
            }
    if (n_noisy == 0)
        printf("none");
}

/* " NAME=VALUE", the value as %.4g; infinities spelled inf and -inf ourselves. */
static void print_number(const char *name, double value)
{
    if (isinf(value))
        printf(" %s=%sinf", name, value < 0 ? "-" : "");
    else
        printf(" %s=%.4g", name, value);
}

/* The block test's fields (compare.c's header; README: Tools). */
static void print_verdict(const struct block_verdict *v)
{
    printf(" blocks_tested=%d blocks_untestable=%d test_block=%d", v->n_tested,
           v->n_untestable, v->size);
    if (v->n_tested > 0) {
        printf(" z_critical=%.4f", v->z_critical);
        print_number("worst_z", v->worst_z);
        printf(" worst_z_block=%d,%d worst_z_channel=%c", v->worst_x0, v->worst_y0,
               "rgb"[v->worst_channel]);
        print_number("worst_z_reldiff", v->worst_relative);
    } else {
        printf(" z_critical=none worst_z=none worst_z_block=none worst_z_channel=none "
               "worst_z_reldiff=none");
    }
    printf(" blocks_failed=%d failed_blocks=", v->n_failed);
    for (int k = 0; k < v->n_failed && k < BLOCK_TEST_LISTED; k++)
        printf("%s%d,%d", k > 0 ? ";" : "", v->failed_x0[k], v->failed_y0[k]);
    printf("%s consistent=%s alpha=%g", v->n_failed == 0                 ? "none"
                                        : v->n_failed > BLOCK_TEST_LISTED ? ";..."
                                                                          : "",
           v->consistent > 0 ? "yes" : v->consistent == 0 ? "no" : "untestable", v->alpha);
}

/* One line on stdout: the metrics and, given a variance or error image, the test's
 * fields; the verdict in *consistent (1 without a test). */
static void print_results(const struct image_error *e, const struct compare_inputs *in,
                          const struct compare_args *args, int *consistent)
{
    print_metrics(e);
    if (args->block_text != NULL) {
        struct block_error w = image_worst_block(in->a, in->b, in->var_b, args->block);
        printf(" worst_block=%.6g worst_block_at=%d,%d blocks=%d blocks_within_3pct=%d",
               w.relative_error, w.x0, w.y0, w.n_blocks, w.n_within);
        if (in->var_b != NULL)
            print_noisy_blocks(in->b, in->var_b, args->block, w.n_noisy);
        /* the whole image as one block: a's mean luminance over b's (inf when b's is 0) */
        double mean_a = block_mean(in->a, 0, 0, in->a->width, in->a->height);
        double mean_b = block_mean(in->b, 0, 0, in->b->width, in->b->height);
        printf(" mean_ratio=%.6g", mean_a == mean_b ? 1.0 : mean_a / mean_b);
    }
    *consistent = 1;
    if (in->var_a != NULL || in->var_b != NULL) {
        struct block_verdict v = image_block_test(in->a, in->b, in->var_a, in->var_b,
                                                  args->block, args->alpha);
        print_verdict(&v);
        *consistent = v.consistent;
    }
    if (args->test_error != NULL || args->test_blocks != NULL) { /* how A's bound held */
        struct bound_check c = bound_check(in->a, in->var_a, in->b, in->var_b,
                                           normal_critical_two_sided(1.0 - args->confidence));
        printf(" bound_blocks=%d bound_covered=%.4f", c.n_blocks,
               c.n_blocks > 0 ? (double)c.covered / c.n_blocks : 0.0);
        if (c.median_ratio < 0) /* every block exact and stated so */
            printf(" bound_median_ratio=none bound_rms_ratio=none");
        else {
            print_number("bound_median_ratio", c.median_ratio);
            print_number("bound_rms_ratio", c.rms_ratio);
        }
    }
    putchar('\n');
}

/* Reads the images, writes the diff if asked, prints the results (the verdict in
 * *consistent); -1 with *err filled (and nothing printed) on bad input. */
static int compare_files(const struct compare_args *args, int *consistent, struct error *err)
{
    struct compare_inputs in = {NULL, NULL, NULL, NULL};
    int status = read_inputs(args, &in, err);
    if (status == 0) {
        struct image_error e = image_compare(in.a, in.b);
        if (args->diff != NULL)
            status = diff_picture_write(args->diff, in.a, in.b, args->diff_absolute, err);
        if (status == 0)
            status = outputs_publish(err);
        if (status == 0)
            print_results(&e, &in, args, consistent);
    }
    image_free(in.var_b);
    image_free(in.var_a);
    image_free(in.b);
    image_free(in.a);
    return status;
}

/* `photon compare --help`: the options and every field printed (README: Tools). */
static const char compare_help[] =
    COMPARE_USAGE_1 COMPARE_INDENT COMPARE_USAGE_2 COMPARE_INDENT COMPARE_USAGE_3
        COMPARE_INDENT COMPARE_USAGE_4 "\n"
    "Compares image A with reference B (PFM, same size); prints one line on stdout.\n"
    "  --diff OUT        a picture of the relative error |A - B| / max(B, 1% of B's\n"
    "                    mean), the worst channel's, in false colour with its scale\n"
    "                    (0 to the 99th percentile: photon convert --help)\n"
    "  --diff-absolute   --diff shows |A - B| instead\n"
    "  --block N         add the block figures; the test's block side (default 16)\n"
    "  --ref-variance V  B's variance of each pixel's mean (photon --variance); so\n"
    "  --test-variance V A's (a side with neither is exact: variance 0)\n"
    "  --ref-error E     B's bound on |pixel - truth| at --confidence C (default\n"
    "  --test-error E    0.95; photon --error); A's. +Inf: no bound\n"
    "  --ref-block-error S  B's bound on each 16 x 16 block's mean, one pixel a\n"
    "  --test-block-error S block (photon --block-error; 2009's pixels share\n"
    "                    photons, so their bounds do not add in quadrature); A's\n"
    "  --alpha ALPHA     chance of calling equal images inconsistent (default 0.01)\n"
    "  --exit-status     exit 0 consistent, 1 inconsistent, 2 bad input or untestable\n"
    "Fields: rmse, relmse (mean of (a-b)^2/(b^2+0.01)), psnr, maxerr over all values.\n"
    "--block: worst_block, the largest |mean A / mean B - 1| of a block's luminance,\n"
    "  worst_block_at=X,Y (its top-left pixel), blocks, blocks_within_3pct, with\n"
    "  --ref-*: blocks_noisy, noisy_blocks (B's standard error over 1%: left out);\n"
    "  mean_ratio = mean A / mean B over the image.\n"
    "With a variance or error image, the block test: in each block and channel z =\n"
    "  (mean A - mean B) / sqrt((sum var_A + sum var_B) / n^2), var = (E / z_C)^2\n"
    "  from an error image, n pixels, or n^2 (S / z_C)^2 for their sum from a block\n"
    "  statement. blocks_tested; blocks_untestable (a pixel of +Inf: not tested);\n"
    "  test_block; z_critical, Sidak's |z| for 3 x blocks_tested tests at level\n"
    "  alpha; worst_z, the largest |z|, in worst_z_block=X,Y and\n"
    "  worst_z_channel=r|g|b, where worst_z_reldiff = mean A / mean B - 1;\n"
    "  blocks_failed (|z| >= z_critical), failed_blocks=X,Y;... (the first 10, then\n"
    "  ...; none); consistent=yes (none failed), no, or untestable (none tested);\n"
    "  alpha. Status without --exit-status: 0, or 2 for bad input.\n"
    "With --test-error or --test-block-error, how A's bound held against B in\n"
    "  16 x 16 blocks (B's mean under 1e-3 aside): bound_blocks; bound_covered, the\n"
    "  share whose |mean A - mean B| is within sqrt(bound^2 + (z_C sigma_B)^2);\n"
    "  bound_median_ratio and bound_rms_ratio, the bound over the error (exact bounds\n"
    "  at 0.95: 2.91 and 1.96).\n";

int compare_command(int argc, char **argv)
{
    assert(argc >= 1 && strcmp(argv[0], "compare") == 0);
    struct error err;
    struct compare_args args;
    int consistent = 1;
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0)
            return fputs(compare_help, stdout) < 0;
    if (parse_compare_args(argc, argv, &args, &err) != 0 ||
        (args.diff != NULL && output_check_one(args.diff, "--diff", &err) < 0) ||
        compare_files(&args, &consistent, &err) != 0) {
        error_print(&err);
        /* 1: the diff's write failed; with --exit-status, 1 is the verdict's */
        return args.exit_status ? EXIT_TROUBLE : error_exit_status(&err);
    }
    if (!args.exit_status)
        return 0;
    return consistent > 0 ? 0 : consistent == 0 ? EXIT_INCONSISTENT : EXIT_TROUBLE;
}
