/*
 * image/compare.c -- error metrics of a test image a against a reference b, a per-pixel
 * statistical test of their agreement, and the `photon compare` command that prints them.
 *
 * Over all n = 3 * width * height channel values, summed in index order:
 *   mse    = (1/n) sum (a - b)^2                 rmse = sqrt(mse)
 *   relmse = (1/n) sum (a - b)^2 / (b^2 + 1e-2)  (the 1e-2 keeps black reference pixels
 *                                                 from dominating, and divisions safe)
 *   psnr   = 10 log10(peak^2 / mse) dB, peak = the largest channel of b; +Inf when
 *            mse = 0, which the command prints as "psnr=inf" (printf's own spelling of
 *            infinity is implementation-defined); none (has_psnr 0, printed
 *            "psnr=none") when b has no positive value and mse > 0: there is no peak
 *   maxerr = max |a - b|
 * Images read from PFM files (floats) always give finite values, except psnr = +Inf.
 *
 * The statistical test (image_consistency). A variance image holds, per pixel and channel,
 * the variance of that pixel's estimate (of the mean, not of single samples). If a and b
 * are independent, normally distributed estimates of the same value, then
 *   z = (a - b) / sqrt(var_a + var_b)
 * is standard normal. Each of the m = 3 * width * height values is tested two-sided at
 * the Sidak level alpha_channel = 1 - (1 - alpha)^(1/m), so that when the m tests are
 * independent the chance that any fails under that hypothesis is exactly alpha: "no pixel
 * fails" (consistent) is a test of the whole image at level alpha. A pixel passes when
 * every channel's |z| < z_critical. Where var_a + var_b = 0 the difference must be exactly
 * 0 (|z| counts as 0, else +Inf). This is z, not Welch's t, because a variance image
 * carries no sample counts. With spp in the hundreds the two agree closely at everyday
 * levels (two-sided 0.01: t with 256 degrees of freedom 2.595, z 2.576) and within a few
 * per cent at the far levels Sidak reaches for a megapixel (1e-6: 5.013 against 4.892),
 * where z is the less conservative.
 *
 * `photon compare A.pfm B.pfm [--diff OUT.png|.ppm]` prints one line
 *   rmse=%.6g relmse=%.6g psnr=%.4f maxerr=%.6g
 * on stdout, or on bad input a message on stderr, nothing on stdout, and status 2. With
 * --ref-variance VB.pfm (b's variance) and/or --test-variance VA.pfm (a's; 0 without),
 * and --alpha ALPHA (default 0.01), the same line goes on with
 *   " pass_fraction=%.6f consistent=yes|no alpha=%g"
 * and --block N puts before those the worst N x N block's relative error of its mean
 * luminance, where it is, the counts, and the whole image's mean luminance ratio a / b:
 *   " worst_block=%.6g worst_block_at=X,Y blocks=%d blocks_within_3pct=%d mean_ratio=%.6g"
 * Options are parsed into struct compare_args: a new flag is one field and one branch.
 */
#include "compare.h"

#include "../base/number.h"
#include "../base/output.h"
#include "png.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#define RELMSE_EPSILON 1e-2 /* compare.h's definition of relmse */
#define COMPARE_USAGE "usage: photon compare A.pfm B.pfm [--diff OUT.png|.ppm] " \
                      "[--ref-variance VB.pfm] [--test-variance VA.pfm] [--alpha ALPHA] " \
                      "[--block N]"
#define DEFAULT_ALPHA 0.01 /* family-wise level of the test when --alpha is not given */
/* Documented limit: the smallest --alpha. Sidak's per-channel level alpha / (3 pixels)
 * stays a positive double down to here for every image size (3 x 2^30 channels at most
 * give 3e-310), as normal_critical_two_sided() needs; a smaller level would round to 0. */
#define ALPHA_MIN 1e-300
#define SQRT2 1.41421356237309504880
/* Upper end of the critical value's bracket: erfc(40 / sqrt(2)) ~ 4e-350 is below the
 * smallest double, so every p > 0 has its root in [0, 40] (p = 1e-300 gives 37.07). */
#define NORMAL_Z_MAX 40.0
#define BISECTION_STEPS 1100 /* enough to reach adjacent doubles from [0, 40], down to 0 */

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

/* Method: bisection on erfc(z / sqrt(2)) = p, which erfc's monotonicity makes safe,
 * until lo and hi are adjacent doubles. Invariant: erfc(lo / sqrt(2)) > p >= erfc(hi /
 * sqrt(2)). Accuracy: the root of the computed erfc to 1 ulp of z; an erfc error of e
 * ulps (glibc: e <= 2) moves z by about e ulps of p times (1 - Phi(z)) / phi(z) < 1/z,
 * which is below z's own ulp. Measured against 20-digit quantiles: within 1e-15 for
 * p >= 1e-9 (z < 6.2), 1.4e-14 at p = 1e-300 (z = 37); the tests hold it to 1e-12. */
double normal_critical_two_sided(double p)
{
    assert(p > 0 && p <= 1);
    double lo = 0.0, hi = NORMAL_Z_MAX;
    if (p >= 1)
        return 0.0; /* erfc(0) = 1: every |z| >= 0 */
    for (int step = 0; step < BISECTION_STEPS; step++) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
            break; /* lo and hi are adjacent doubles */
        if (erfc(mid / SQRT2) > p)
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}

static double variance_at(const struct image *var, size_t i, int c)
{
    return var != NULL ? vec3_get(var->pixels[i], c) : 0.0; /* NULL: an exact image */
}

/* The largest |z| over pixel i's channels (compare.c's header); +Inf for a difference
 * where both variances are 0, which no critical value passes. */
static double pixel_abs_z(const struct image *a, const struct image *b,
                          const struct image *var_a, const struct image *var_b, size_t i)
{
    double worst = 0.0;
    for (int c = 0; c < 3; c++) {
        double d = fabs(vec3_get(a->pixels[i], c) - vec3_get(b->pixels[i], c));
        double var = variance_at(var_a, i, c) + variance_at(var_b, i, c);
        double z = var > 0 ? d / sqrt(var) : (d > 0 ? HUGE_VAL : 0.0);
        worst = fmax(worst, z);
    }
    return worst;
}

struct consistency image_consistency(const struct image *a, const struct image *b,
                                     const struct image *var_a, const struct image *var_b,
                                     double alpha)
{
    assert(a->width == b->width && a->height == b->height);
    assert(alpha > 0 && alpha < 1);
    struct consistency s;
    s.alpha = alpha;
    s.n_pixels = (size_t)a->width * (size_t)a->height; /* >= 1 */
    /* Sidak: 1 - (1 - alpha)^(1/m), as -expm1(log1p(-alpha) / m) so that a level of
     * 1e-12 keeps its digits instead of cancelling against 1. */
    s.alpha_channel = -expm1(log1p(-alpha) / (3.0 * (double)s.n_pixels));
    s.z_critical = normal_critical_two_sided(s.alpha_channel);
    s.n_failed = 0;
    s.worst_pixel = 0;
    s.worst_z = 0.0;
    for (size_t i = 0; i < s.n_pixels; i++) {
        double z = pixel_abs_z(a, b, var_a, var_b, i);
        if (!(z < s.z_critical))
            s.n_failed++;
        if (z > s.worst_z) {
            s.worst_z = z;
            s.worst_pixel = i;
        }
    }
    s.pass_fraction = (double)(s.n_pixels - s.n_failed) / (double)s.n_pixels;
    s.consistent = s.n_failed == 0;
    return s;
}

/* The first value of var (in row order, then channel) that is negative, as its index
 * 3 * pixel + channel, or -1 when there is none. */
static long long first_negative(const struct image *var)
{
    size_t n_pixels = (size_t)var->width * (size_t)var->height;
    for (size_t i = 0; i < n_pixels; i++)
        for (int c = 0; c < 3; c++)
            if (!(vec3_get(var->pixels[i], c) >= 0))
                return 3 * (long long)i + c;
    return -1;
}

struct image *variance_read(const char *name, const struct image *like, struct error *err)
{
    struct image *var = pfm_read(name, err); /* refuses NaN and Inf */
    if (var == NULL)
        return NULL;
    if (var->width != like->width || var->height != like->height) {
        error_set(err, name, 0, "variance image is %dx%d, but the images compared are "
                                "%dx%d", var->width, var->height, like->width, like->height);
        image_free(var);
        return NULL;
    }
    long long k = first_negative(var);
    if (k >= 0) {
        long long pixel = k / 3;
        error_set(err, name, 0, "pixel (%lld, %lld) from the top left has a negative "
                                "variance %g in channel %lld; variances must be >= 0",
                  pixel % var->width, pixel / var->width,
                  vec3_get(var->pixels[pixel], (int)(k % 3)), k % 3);
        image_free(var);
        return NULL;
    }
    return var;
}

/* What `photon compare` was asked to do. */
struct compare_args {
    const char *test;          /* A.pfm, the image judged                     */
    const char *reference;     /* B.pfm, the reference it is judged by          */
    const char *diff;          /* --diff OUT.png or .ppm, or NULL                     */
    const char *ref_variance;  /* --ref-variance VB.pfm (b's variance), or NULL */
    const char *test_variance; /* --test-variance VA.pfm (a's variance), or NULL */
    const char *alpha_text;    /* --alpha as given, or NULL                     */
    double alpha;              /* the test's level, from alpha_text or DEFAULT_ALPHA */
    const char *block_text;    /* --block as given, or NULL                     */
    int block;                 /* > 0: report the worst block of this size      */
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

/* The field an option's value goes to, or NULL when arg is not an option with a value. */
static const char **option_value(struct compare_args *args, const char *arg)
{
    if (strcmp(arg, "--diff") == 0)
        return &args->diff;
    if (strcmp(arg, "--ref-variance") == 0)
        return &args->ref_variance;
    if (strcmp(arg, "--test-variance") == 0)
        return &args->test_variance;
    if (strcmp(arg, "--alpha") == 0)
        return &args->alpha_text;
    if (strcmp(arg, "--block") == 0)
        return &args->block_text;
    return NULL;
}

/* --alpha: a number strictly between 0 and 1, meaningful only with a variance image. */
static int parse_alpha(struct compare_args *args, struct error *err)
{
    args->alpha = DEFAULT_ALPHA;
    if (args->alpha_text == NULL)
        return 0;
    if (args->ref_variance == NULL && args->test_variance == NULL)
        return error_set(err, "", 0, "compare: --alpha needs --ref-variance or "
                                     "--test-variance; " COMPARE_USAGE);
    if (!number_parse(args->alpha_text, 0, &args->alpha) ||
        !(args->alpha >= ALPHA_MIN && args->alpha < 1))
        return error_set(err, "", 0, "compare: --alpha '%s' must be a number from %g up to "
                                     "1 (exclusive), such as 0.01", args->alpha_text,
                         ALPHA_MIN);
    return 0;
}

/* --block: a whole number of pixels, 1 to 65536. */
static int parse_block(struct compare_args *args, struct error *err)
{
    args->block = 0;
    if (args->block_text == NULL)
        return 0;
    double size;
    if (!number_parse(args->block_text, 1, &size) || size < 1 || size > 65536)
        return error_set(err, "", 0, "compare: --block '%s' must be a whole number of pixels "
                                     "from 1 to 65536; " COMPARE_USAGE, args->block_text);
    args->block = (int)size;
    return 0;
}

static int parse_compare_args(int argc, char **argv, struct compare_args *args,
                              struct error *err)
{
    const char *files[2] = {NULL, NULL};
    int n_files = 0;
    args->diff = args->ref_variance = args->test_variance = args->alpha_text = NULL;
    args->block_text = NULL;
    for (int i = 1; i < argc; i++) {
        const char **value = option_value(args, argv[i]);
        if (value != NULL) {
            if (i + 1 == argc)
                return error_set(err, "", 0, "compare: %s needs a %s; " COMPARE_USAGE,
                                 argv[i],
                                 value == &args->alpha_text || value == &args->block_text
                                     ? "number"
                                     : "file name");
            *value = argv[++i];
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
    return parse_alpha(args, err) < 0 ? -1 : parse_block(args, err);
}

/* --diff: |a - b| per channel divided by maxerr, so the largest error shows as full white
 * and identical images as black; sRGB-encoded like any display image we write, a PNG or
 * a PPM by the name's ending (parse_compare_args refused any other). */
static int write_diff(const char *name, const struct image *a, const struct image *b,
                      double maxerr, struct error *err)
{
    struct image *diff = image_create(a->width, a->height);
    double inv_maxerr = maxerr > 0 ? 1.0 / maxerr : 0.0; /* every |a - b| <= maxerr */
    size_t n_pixels = (size_t)a->width * (size_t)a->height;
    for (size_t i = 0; i < n_pixels; i++) {
        struct vec3 d = vec3_sub(a->pixels[i], b->pixels[i]);
        diff->pixels[i] = vec3_scale(vec3(fabs(d.x), fabs(d.y), fabs(d.z)), inv_maxerr);
    }
    size_t n = strlen(name);
    int status = strcmp(name + n - 4, display_suffix(DISPLAY_PPM)) == 0
                     ? ppm_write(name, diff, 1.0, err)
                     : png_write(name, diff, 1.0, err);
    image_free(diff);
    return status;
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
    struct image *a, *b;         /* test and reference             */
    struct image *var_a, *var_b; /* their variances, when given    */
};

/* Reads every input named in args and checks their sizes; -1 with *err filled, leaving
 * what was read in *in for the caller to free. */
static int read_inputs(const struct compare_args *args, struct compare_inputs *in,
                       struct error *err)
{
    in->a = pfm_read(args->test, err);
    if (in->a == NULL)
        return error_set(err, err->file, err->line, "%s (A, the image tested)", err->message);
    in->b = pfm_read(args->reference, err);
    if (in->b == NULL)
        return error_set(err, err->file, err->line, "%s (B, the reference)", err->message);
    if (in->a->width != in->b->width || in->a->height != in->b->height)
        return error_set(err, args->test, 0, "size %dx%d differs from %s: %dx%d",
                         in->a->width, in->a->height, args->reference, in->b->width,
                         in->b->height);
    if (args->test_variance != NULL) {
        in->var_a = variance_read(args->test_variance, in->a, err);
        if (in->var_a == NULL)
            return -1;
    }
    if (args->ref_variance != NULL) {
        in->var_b = variance_read(args->ref_variance, in->a, err);
        if (in->var_b == NULL)
            return -1;
    }
    return 0;
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

/* One line on stdout: the metrics and, given a variance image, the test's fields. */
static void print_results(const struct image_error *e, const struct compare_inputs *in,
                          const struct compare_args *args)
{
    print_metrics(e);
    if (args->block > 0) {
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
    if (in->var_a != NULL || in->var_b != NULL) {
        struct consistency s = image_consistency(in->a, in->b, in->var_a, in->var_b,
                                                 args->alpha);
        printf(" pass_fraction=%.6f consistent=%s alpha=%g", s.pass_fraction,
               s.consistent ? "yes" : "no", s.alpha);
    }
    putchar('\n');
}

/* Reads the images, writes the diff if asked, prints the results; -1 with *err filled
 * (and nothing printed) on bad input. */
static int compare_files(const struct compare_args *args, struct error *err)
{
    struct compare_inputs in = {NULL, NULL, NULL, NULL};
    int status = read_inputs(args, &in, err);
    if (status == 0) {
        struct image_error e = image_compare(in.a, in.b);
        if (args->diff != NULL)
            status = write_diff(args->diff, in.a, in.b, e.maxerr, err);
        if (status == 0)
            status = outputs_publish(err);
        if (status == 0)
            print_results(&e, &in, args);
    }
    image_free(in.var_b);
    image_free(in.var_a);
    image_free(in.b);
    image_free(in.a);
    return status;
}

int compare_command(int argc, char **argv)
{
    assert(argc >= 1 && strcmp(argv[0], "compare") == 0);
    struct error err;
    struct compare_args args;
    if (parse_compare_args(argc, argv, &args, &err) != 0 ||
        (args.diff != NULL && output_check_one(args.diff, "--diff", &err) < 0) ||
        compare_files(&args, &err) != 0) {
        error_print(&err);
        return error_exit_status(&err); /* 1: the diff's write failed */
    }
    return 0;
}
