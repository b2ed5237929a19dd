/*
 * image/compare.c -- error metrics of a test image a against a reference b, and the
 * `photon compare` command that prints them.
 *
 * Over all n = 3 * width * height channel values, summed in index order:
 *   mse    = (1/n) sum (a - b)^2                 rmse = sqrt(mse)
 *   relmse = (1/n) sum (a - b)^2 / (b^2 + 1e-2)  (the 1e-2 keeps black reference pixels
 *                                                 from dominating, and divisions safe)
 *   psnr   = 10 log10(peak^2 / mse) dB, peak = max(largest channel of b, 1e-30);
 *            +Inf when mse = 0, which the command prints as "psnr=inf" (printf's own
 *            spelling of infinity is implementation-defined)
 *   maxerr = max |a - b|
 * Images read from PFM files (floats) always give finite values, except psnr = +Inf.
 *
 * `photon compare A.pfm B.pfm [--diff OUT.ppm]` prints one line
 *   rmse=%.6g relmse=%.6g psnr=%.4f maxerr=%.6g
 * on stdout, or on bad input a message on stderr, nothing on stdout, and status 2.
 * Options are parsed into struct compare_args, so a later flag (--ref-variance) is one
 * field and one branch.
 */
#include "compare.h"

#include <assert.h>
#include <string.h>

#define RELMSE_EPSILON 1e-2 /* compare.h's definition of relmse */
#define PSNR_MIN_PEAK 1e-30 /* compare.h: keeps peak^2 > 0 for an all-black reference */
#define COMPARE_USAGE "usage: photon compare A.pfm B.pfm [--diff OUT.ppm]"

struct image_error image_compare(const struct image *a, const struct image *b)
{
    assert(a->width == b->width && a->height == b->height);
    size_t n_pixels = (size_t)a->width * (size_t)a->height;
    double sum2 = 0, sum_rel = 0, peak = PSNR_MIN_PEAK, maxerr = 0;
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
    e.psnr = mse > 0 ? 10.0 * log10(peak * peak / mse) : HUGE_VAL;
    e.maxerr = maxerr;
    return e;
}

/* What `photon compare` was asked to do. */
struct compare_args {
    const char *test;      /* A.pfm, the image judged            */
    const char *reference; /* B.pfm, the reference it is judged by */
    const char *diff;      /* --diff OUT.ppm, or NULL              */
};

static int parse_compare_args(int argc, char **argv, struct compare_args *args,
                              struct error *err)
{
    const char *files[2] = {NULL, NULL};
    int n_files = 0;
    args->test = args->reference = args->diff = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--diff") == 0) {
            if (i + 1 == argc)
                return error_set(err, "", 0, "compare: --diff needs a file name; "
                                             COMPARE_USAGE);
            args->diff = argv[++i];
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
    return 0;
}

/* --diff: |a - b| per channel divided by maxerr, so the largest error shows as full white
 * and identical images as black; sRGB-encoded like any PPM we write. */
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
    int status = ppm_write(name, diff, 1.0, err);
    image_free(diff);
    return status;
}

static void print_metrics(const struct image_error *e)
{
    printf("rmse=%.6g relmse=%.6g ", e->rmse, e->relmse);
    if (isinf(e->psnr))
        printf("psnr=inf");
    else
        printf("psnr=%.4f", e->psnr);
    printf(" maxerr=%.6g\n", e->maxerr);
}

/* Reads both images, writes the diff if asked, prints the metrics; -1 with *err filled
 * (and nothing printed) on bad input. */
static int compare_files(const struct compare_args *args, struct error *err)
{
    struct image *b = NULL;
    struct image *a = pfm_read(args->test, err);
    if (a == NULL)
        goto fail;
    b = pfm_read(args->reference, err);
    if (b == NULL)
        goto fail;
    if (a->width != b->width || a->height != b->height) {
        error_set(err, args->test, 0, "size %dx%d differs from %s: %dx%d", a->width,
                  a->height, args->reference, b->width, b->height);
        goto fail;
    }
    struct image_error e = image_compare(a, b);
    if (args->diff != NULL && write_diff(args->diff, a, b, e.maxerr, err) != 0)
        goto fail;
    print_metrics(&e);
    image_free(b);
    image_free(a);
    return 0;
fail:
    image_free(b);
    image_free(a);
    return -1;
}

int compare_command(int argc, char **argv)
{
    assert(argc >= 1 && strcmp(argv[0], "compare") == 0);
    struct error err;
    struct compare_args args;
    if (parse_compare_args(argc, argv, &args, &err) != 0 || compare_files(&args, &err) != 0) {
        error_print(&err);
        return 2;
    }
    return 0;
}
