/*
 * image/compare.h -- error metrics between a test image and a reference, the statistical
 * test of their agreement on block means given variance or error images, and the
 * `photon compare` command built on them.
 */
#ifndef PHOTON_COMPARE_H
#define PHOTON_COMPARE_H

#include "../base/normal.h"
#include "../base/option_equals.h"
#include "image.h"

/* The metrics `photon compare` prints; definitions in compare.c and the README. */
struct image_error {
    double rmse;   /* sqrt(mean over pixels and channels of (a - b)^2)                 */
    double relmse; /* mean over pixels and channels of (a - b)^2 / (b^2 + 1e-2)       */
    double psnr;   /* 10 log10(peak^2 / mse), peak = max over b's channels; +Inf for
                      mse = 0; 0 when has_psnr is 0                                    */
    int has_psnr;  /* 0 when b has no positive value and mse > 0: no peak to speak of  */
    double maxerr; /* max over pixels and channels of |a - b|                          */
};

/* Metrics of test image a against reference b (same size, checked by the caller). */
struct image_error image_compare(const struct image *a, const struct image *b);

/* The tolerance of the per-block claims the documentation makes ("every 16 x 16 block
 * within 3% of the reference"). */
#define BLOCK_TOLERANCE 0.03

/* A block of reference b is below its noise floor when the standard error of its mean
 * luminance, from b's variance image, exceeds this share of the mean: a third of
 * BLOCK_TOLERANCE, so that a block counted as within the tolerance is so by more than
 * the reference's own noise at three standard errors. */
#define BLOCK_NOISE_FLOOR (BLOCK_TOLERANCE / 3.0)

/* The block of image_worst_block(): where it is and how far off its mean is, and how many
 * blocks there are and how many of them are within BLOCK_TOLERANCE. */
struct block_error {
    int x0, y0;            /* its top-left pixel                                          */
    double relative_error; /* |mean_a - mean_b| / mean_b of the block's luminance           */
    int n_blocks;          /* blocks in the image, the noisy ones left out                 */
    int n_within;          /* of them, those whose relative error is at most
                              BLOCK_TOLERANCE                                              */
    int n_noisy;           /* blocks below b's noise floor (block_is_noisy()), left out    */
};

/* Whether the size x size block at (x0, y0) of reference b is below its noise floor
 * (BLOCK_NOISE_FLOOR) by var_b, b's variance of each pixel's mean: the block mean's
 * standard error is sqrt(sum of the pixels' luminance variances) / n, each pixel's taken
 * at its largest for its channels' variances, (sum_c w_c sqrt(var_c))^2 (the channels of
 * one estimate are correlated), pixels independent. Never without var_b (NULL). */
int block_is_noisy(const struct image *b, const struct image *var_b, int x0, int y0,
                   int size);

/* Splits the images (same size) into size x size blocks from the top left (those at the
 * right and bottom edges may be smaller) and returns the block whose mean luminance in a
 * differs most, relatively, from its mean in b, with the counts; blocks below b's noise
 * floor by var_b (NULL: none) are counted apart and left out. Blocks whose mean in b is
 * zero count when a's is not (relative error +Inf). size >= 1. */
struct block_error image_worst_block(const struct image *a, const struct image *b,
                                     const struct image *var_b, int size);

/* The per-pixel test of image_consistency(); definitions in compare.c. `photon compare`
 * no longer uses it (it cries wolf and is blind to block errors: image_block_test() is
 * the verdict); tests/test_pt.c still does. */
struct consistency {
    double alpha;         /* family-wise level asked for, 0 < alpha < 1                    */
    double alpha_channel; /* Sidak level of one channel's test: 1 - (1 - alpha)^(1/(3 n))  */
    double z_critical;    /* two-sided critical |z| at alpha_channel                       */
    size_t n_pixels;      /* n = width * height                                            */
    size_t n_failed;      /* pixels with some channel's |z| >= z_critical                  */
    double pass_fraction; /* (n_pixels - n_failed) / n_pixels                              */
    int consistent;       /* 1 when n_failed == 0: a test of "same means" at level alpha   */
    size_t worst_pixel;   /* index y * width + x of the largest |z| (0 when all z are 0)   */
    double worst_z;       /* that |z|; +Inf for a difference where both variances are 0    */
};

/* Tests, per pixel and channel, whether test image a and reference b have the same mean
 * given the variances of their estimates: z = (a - b) / sqrt(var_a + var_b). var_a or
 * var_b may be NULL (an exact image, variance 0). Caller guarantees: same sizes, finite
 * values, variances >= 0 (variance_read checks files), 0 < alpha < 1. */
struct consistency image_consistency(const struct image *a, const struct image *b,
                                     const struct image *var_a, const struct image *var_b,
                                     double alpha);

/* Reads a variance image for comparison with image like: a PFM of like's size whose
 * values are all >= 0 (pfm_read refuses non-finite ones). NULL with *err filled. */
struct image *variance_read(const char *name, const struct image *like, struct error *err);

/* Reads an error image for comparison with image like: a PFM of like's size holding a
 * bound B >= 0 on |image - truth| per pixel and channel at the given confidence
 * (0 < confidence < 1, 1 - confidence > 0 as a double), or +Inf where the renderer cannot
 * bound the pixel; NaN and negative values are refused. Returned as the variance image
 * the block test takes: (B / z)^2 with z the two-sided normal quantile of 1 - confidence
 * (1.96 at 0.95), +Inf kept. NULL with *err filled. */
struct image *error_image_read(const char *name, const struct image *like, double confidence,
                               struct error *err);

/* Reads a block statement (photon --block-error) for comparison with image like: a PFM
 * of one pixel a 16 x 16 block of like (ERROR_BLOCK, the grid from its top left, cut at
 * its edges), each value a bound B >= 0 (or +Inf) on |block mean - truth| at the given
 * confidence. Returned as the variance image the block test takes, n (B / z)^2 at each
 * of a block's n pixels, so that the block mean's variance, their sum over n^2, is
 * (B / z)^2: a statement of blocks the test reads only in blocks of 16. NULL with *err
 * filled. */
struct image *block_error_read(const char *name, const struct image *like, double confidence,
                               struct error *err);

/* The whole-image test of image_block_test(); definitions in compare.c's header. */
#define BLOCK_TEST_LISTED 10 /* failed blocks named in block_verdict, the first in row order */
struct block_verdict {
    double alpha;          /* family-wise level asked for, 0 < alpha < 1                  */
    int size;              /* side of the blocks, >= 1                                   */
    int n_tested;          /* blocks whose variances are all finite                      */
    int n_untestable;      /* blocks with a pixel of variance +Inf (an unbounded error)  */
    double alpha_one;      /* Sidak level of one channel of one block:
                              1 - (1 - alpha)^(1/(3 n_tested)); 0 when n_tested is 0     */
    double z_critical;     /* two-sided critical |z| at alpha_one; 0 when n_tested is 0   */
    int n_failed;          /* tested blocks with some channel's |z| >= z_critical         */
    int failed_x0[BLOCK_TEST_LISTED], failed_y0[BLOCK_TEST_LISTED]; /* the first of them */
    double worst_z;        /* largest |z| of a tested block's channel (0 when none; +Inf
                              for a difference where the variances are 0)                */
    int worst_x0, worst_y0; /* that block's top-left pixel                                */
    int worst_channel;     /* and channel, 0 1 2 for R G B; -1 when nothing was tested   */
    double worst_relative; /* that block and channel's (mean_a - mean_b) / mean_b, signed;
                              +-Inf when mean_b is 0 and mean_a is not, 0 when equal      */
    int consistent;        /* 1: no tested block failed; 0: some did; -1: none tested     */
};

/* Tests whether test image a and reference b have the same expected block means, per
 * size x size block (from the top left; those at the right and bottom edges may be
 * smaller) and channel, given the variances of the pixels' estimates (var_a or var_b
 * NULL: an exact image), at family-wise level alpha (compare.c's header). Caller
 * guarantees: same sizes, finite a and b, variances >= 0 or +Inf (no NaN), size >= 1,
 * 0 < alpha < 1 with a positive Sidak level (compare.c's ALPHA_MIN). */
struct block_verdict image_block_test(const struct image *a, const struct image *b,
                                      const struct image *var_a, const struct image *var_b,
                                      int size, double alpha);

/* `photon compare A.pfm B.pfm [--diff OUT.png|.ppm] [--ref-variance VB.pfm | --ref-error
 * EB.pfm] [--test-variance VA.pfm | --test-error EA.pfm] [--confidence C] [--alpha ALPHA]
 * [--block N] [--exit-status]`: argv[0] is "compare". Returns the exit status: 0, or 2 for
 * bad input (messages on stderr), 1 for a --diff that could not be written; with
 * --exit-status 0 consistent, 1 inconsistent, 2 bad input or no block testable. */
int compare_command(int argc, char **argv);

/* Its options, for --NAME=VALUE (app/commands.h); a NULL name ends them. */
extern const struct option_arity compare_options[];

#endif
