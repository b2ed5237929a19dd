/*
 * tests/test_compare.c -- the statistical tests of `photon compare`: normal critical
 * values against tabulated quantiles, the per-pixel test (image_consistency, the block
 * test with blocks of one pixel, which tests/test_pt.c uses) on synthetic images with
 * Gaussian noise of known variance, variance images that must be refused, the command's
 * output line on the built binary, and the block figures of --block. The block test
 * (image_block_test), the command's verdict, is tested in test_compare_verdict.c; the
 * metrics themselves (rmse, psnr, ...) in test_image.c.
 *
 * Noise is drawn from the test stream by Box-Muller, keyed by (seed, pixel, channel), so
 * every image here is the same on every run and platform.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/image/compare.h"
#include "check.h"
#include "files.h"
#include "tests.h"

#define NAME_MAX_BYTES 256
#define SIDE 64                /* synthetic images are SIDE x SIDE: 12288 channel tests */
#define SEED_REFERENCE 11      /* the two independent draws of the synthetic images */
#define SEED_TEST 12

/* truth: tabulated standard normal quantiles, computed to 20 digits with mpmath as the
 *   root of erfc(z / sqrt(2)) = p (and agreeing with the usual tables: 0.05 -> 1.95996,
 *   0.01 -> 2.57583), from p = 0.5 out to 1e-300.
 * tolerance: 1e-12 absolute (the method's bound in compare.c is ~1e-15; libm's erfc is
 *   the limit).
 * catches: a one-sided quantile (1.645 for 0.05), erfc's argument not divided by sqrt 2,
 *   a bisection stopped early, a bracket too narrow for far tails, p = 1 looping. */
static void test_critical_values(struct check *t)
{
    static const double table[][2] = {
        {0.5, 0.6744897501960817432}, {0.05, 1.9599639845400542355},
        {0.01, 2.575829303548900761}, {1e-3, 3.2905267314918947932},
        {1e-6, 4.8916384756985903862}, {1e-9, 6.1094102048693971399},
        {1e-20, 9.3360448492340600354}, {1e-100, 21.305940069351527446},
        {1e-300, 37.065787880772130393},
    };
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        CHECK_CLOSE(t, normal_critical_two_sided(table[i][0]), table[i][1], 1e-12);
    CHECK(t, normal_critical_two_sided(1.0) == 0.0);
}

/* An image of n x n pixels whose value is f(x, y, c). */
static struct image *image_of(int n, double (*f)(int x, int y, int c))
{
    struct image *img = image_create(n, n);
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++)
            image_set(img, x, y, vec3(f(x, y, 0), f(x, y, 1), f(x, y, 2)));
    return img;
}

/* The known means: smooth, positive, different per channel. */
static double mean_at(int x, int y, int c)
{
    return 0.05 + 0.01 * (x + 2 * y) + 0.2 * c;
}

/* Standard deviations of the two estimates: the reference's varies over the image. */
static double sigma_reference(int x, int y, int c)
{
    return 0.01 * mean_at(x, y, c) * (1 + x % 3);
}
static double sigma_test(int x, int y, int c)
{
    return 0.03 * mean_at(x, y, c);
}
static double var_reference(int x, int y, int c)
{
    return sigma_reference(x, y, c) * sigma_reference(x, y, c);
}
static double var_test(int x, int y, int c)
{
    return sigma_test(x, y, c) * sigma_test(x, y, c);
}

/* A standard normal number keyed by (seed, pixel, channel): Box-Muller on two uniforms,
 * 1 - u1 in (0, 1] so the logarithm is finite. */
static double normal_number(uint64_t seed, int x, int y, int c)
{
    struct rng r = rng_stream(seed, STREAM_TEST, (uint64_t)(y * SIDE + x), (uint64_t)c);
    double u1 = rng_uniform(&r), u2 = rng_uniform(&r);
    return sqrt(-2.0 * log(1.0 - u1)) * cos(2.0 * PI * u2);
}

/* mean + sigma * N(0, 1) for every value of an image. */
static struct image *noisy_image(uint64_t seed, double (*sigma)(int x, int y, int c))
{
    struct image *img = image_create(SIDE, SIDE);
    for (int y = 0; y < SIDE; y++)
        for (int x = 0; x < SIDE; x++) {
            double v[3];
            for (int c = 0; c < 3; c++)
                v[c] = mean_at(x, y, c) + sigma(x, y, c) * normal_number(seed, x, y, c);
            image_set(img, x, y, vec3(v[0], v[1], v[2]));
        }
    return img;
}

/* truth: the Sidak level in closed form, 1 - (1 - alpha)^(1/(3 n)), and its quantile, by
 *   mpmath to 20 digits: one pixel at 0.05 -> 0.016952427508441499 and 2.3877378870708155;
 *   64 x 64 pixels at 0.01 -> 8.1789809109909067e-7 and 4.9310475765497026. On a 1x1
 *   image a difference of 2.39 sigma then fails and 2.38 passes: Bonferroni (0.05 / 3,
 *   critical 2.394) would pass both; one test per pixel instead of per channel (1.96)
 *   would fail both.
 * tolerance: 1e-14 relative for the level (expm1 and log1p keep its digits), 1e-12 for z.
 * catches: 1 - pow(1 - alpha, 1/m) losing digits to cancellation, m = pixels instead of
 *   channel values, Bonferroni for Sidak, worst_z not the largest |z|. */
static void test_sidak_level(struct check *t)
{
    struct image *a = image_create(1, 1), *b = image_create(1, 1), *var = image_create(1, 1);
    image_set(var, 0, 0, vec3(4, 4, 4)); /* sigma 2 */
    struct consistency s = image_consistency(a, b, NULL, var, 0.05);
    CHECK_CLOSE(t, s.alpha_channel, 0.016952427508441499, 1e-14 * 0.017);
    CHECK_CLOSE(t, s.z_critical, 2.3877378870708155, 1e-12);
    CHECK(t, s.consistent && s.n_failed == 0 && s.pass_fraction == 1 && s.worst_z == 0);
    image_set(a, 0, 0, vec3(0, 2 * 2.39, 0));
    s = image_consistency(a, b, NULL, var, 0.05);
    CHECK(t, !s.consistent && s.n_failed == 1 && s.pass_fraction == 0);
    CHECK_CLOSE(t, s.worst_z, 2.39, 1e-15);
    image_set(a, 0, 0, vec3(0, 2 * 2.38, 0));
    s = image_consistency(a, b, NULL, var, 0.05);
    CHECK(t, s.consistent && s.n_failed == 0);
    image_free(var);
    image_free(b);
    image_free(a);
    a = image_create(SIDE, SIDE);
    s = image_consistency(a, a, NULL, a, 0.01);
    CHECK_CLOSE(t, s.alpha_channel, 8.1789809109909067e-7, 1e-14 * 8.2e-7);
    CHECK_CLOSE(t, s.z_critical, 4.9310475765497026, 1e-12);
    CHECK(t, s.n_pixels == SIDE * SIDE && s.consistent);
    image_free(a);
}

/* truth: two independent draws around the same known means, each with its known
 *   variance, are consistent at alpha = 0.01 (the chance of a false "no" is 1%, and
 *   these fixed seeds are not in it); swapping the roles changes nothing (|z| is
 *   symmetric); leaving out the test's variance (3x the reference's sigma, so z's spread
 *   is sqrt(10) too wide) must fail, since the largest of 12288 such |z| is ~12 > 4.93.
 * tolerance: none; counts.
 * catches: var_a ignored, the variance taken as a standard deviation (z ~ 10x too small
 *   and the 2% bias below unseen) or squared, a test that only ever says yes. */
static void test_consistent_noise(struct check *t)
{
    struct image *b = noisy_image(SEED_REFERENCE, sigma_reference);
    struct image *a = noisy_image(SEED_TEST, sigma_test);
    struct image *var_b = image_of(SIDE, var_reference), *var_a = image_of(SIDE, var_test);
    struct consistency s = image_consistency(a, b, var_a, var_b, 0.01);
    CHECK(t, s.consistent && s.n_failed == 0 && s.pass_fraction == 1.0);
    CHECK(t, s.worst_z > 2 && s.worst_z < s.z_critical); /* noise, but none too large */
    struct consistency swapped = image_consistency(b, a, var_b, var_a, 0.01);
    CHECK(t, swapped.consistent && swapped.worst_z == s.worst_z);
    s = image_consistency(a, b, NULL, var_b, 0.01);
    CHECK(t, !s.consistent && s.n_failed > 0 && s.pass_fraction < 1);
    image_free(var_a);
    image_free(var_b);
    image_free(a);
    image_free(b);
}

static double sigma_small(int x, int y, int c)
{
    return 0.001 * mean_at(x, y, c);
}
static double var_small(int x, int y, int c)
{
    return sigma_small(x, y, c) * sigma_small(x, y, c);
}

/* truth: a bias of 2% of the mean in one channel, against sigma = 0.1% of the mean in
 *   each image, is z ~ 0.02 / (0.001 sqrt 2) = 14 at every pixel: every pixel fails, and
 *   the same images without the bias pass (so the bias, not the noise, fails them).
 * tolerance: none; counts. 14 - 4.93 is 9 standard deviations: no pixel passes by chance.
 * catches: only the first channel tested, a mean over channels hiding one, the bias
 *   averaged away over the image (a global instead of a per-pixel test). */
static void test_bias_detected(struct check *t)
{
    struct image *b = noisy_image(SEED_REFERENCE, sigma_small);
    struct image *a = noisy_image(SEED_TEST, sigma_small);
    struct image *var = image_of(SIDE, var_small);
    struct consistency s = image_consistency(a, b, var, var, 0.01);
    CHECK(t, s.consistent);
    for (size_t i = 0; i < (size_t)SIDE * SIDE; i++)
        a->pixels[i].z *= 1.02;
    s = image_consistency(a, b, var, var, 0.01);
    CHECK(t, !s.consistent && s.n_failed == s.n_pixels && s.pass_fraction == 0);
    CHECK(t, s.worst_z > 10);
    image_free(var);
    image_free(a);
    image_free(b);
}

/* truth: one value moved by 10 combined standard deviations (z ~ 10 +- 1 against a
 *   critical 4.93) fails that pixel and no other, whichever the sign.
 * tolerance: none; the index of the pixel, and pass_fraction = 4095 / 4096 exactly.
 * catches: |z| without the absolute value (a negative outlier passing), a failure
 *   counted per channel or in the wrong pixel, worst_pixel not following the maximum. */
static void test_single_outlier(struct check *t)
{
    struct image *b = noisy_image(SEED_REFERENCE, sigma_reference);
    struct image *a = noisy_image(SEED_TEST, sigma_test);
    struct image *var_b = image_of(SIDE, var_reference), *var_a = image_of(SIDE, var_test);
    const int x = 17, y = 42;
    double sigma = sqrt(var_reference(x, y, 1) + var_test(x, y, 1));
    const struct vec3 drawn = image_get(a, x, y);
    for (int sign = -1; sign <= 1; sign += 2) {
        image_set(a, x, y, vec3(drawn.x, drawn.y + sign * 10.0 * sigma, drawn.z));
        struct consistency s = image_consistency(a, b, var_a, var_b, 0.01);
        CHECK(t, !s.consistent && s.n_failed == 1);
        CHECK(t, s.worst_pixel == (size_t)(y * SIDE + x) && s.worst_z > 8);
        CHECK(t, s.pass_fraction == 4095.0 / 4096.0);
    }
    image_free(var_a);
    image_free(var_b);
    image_free(a);
    image_free(b);
}

/* truth: the rule for zero variance in compare.c: with both variances 0 a pixel passes
 *   only when a == b exactly (|z| = 0, else +Inf); with one of them 0 the other decides;
 *   a NULL variance image is the same as an all-zero one.
 * tolerance: none.
 * catches: 0 / 0 = NaN, which compares false and would pass or fail by accident; a
 *   difference of 1e-300 passing as "small"; NULL and zero images treated differently. */
static void test_zero_variance(struct check *t)
{
    struct image *a = image_create(2, 1), *b = image_create(2, 1);
    struct image *zero = image_create(2, 1), *var = image_create(2, 1);
    image_set(a, 0, 0, vec3(1, 2, 3));
    image_set(b, 0, 0, vec3(1, 2, 3));
    struct consistency s = image_consistency(a, b, NULL, NULL, 0.01);
    CHECK(t, s.consistent && s.worst_z == 0);
    s = image_consistency(a, b, zero, zero, 0.01);
    CHECK(t, s.consistent && s.worst_z == 0);
    image_set(a, 1, 0, vec3(0, 0, 1e-300));
    s = image_consistency(a, b, NULL, zero, 0.01);
    CHECK(t, !s.consistent && s.n_failed == 1 && s.worst_pixel == 1 && isinf(s.worst_z));
    image_set(var, 1, 0, vec3(0, 0, ldexp(1.0, -1000))); /* z = 1e-300 / 2^-500 ~ 3e-150 */
    s = image_consistency(a, b, var, NULL, 0.01);
    CHECK(t, s.consistent && s.worst_z > 0 && s.worst_z < 1e-100);
    s = image_consistency(a, b, zero, var, 0.01);
    CHECK(t, s.consistent && s.worst_z > 0 && s.worst_z < 1e-100);
    image_free(var);
    image_free(zero);
    image_free(b);
    image_free(a);
}

/* Writes img to a PFM under name; returns 0 on success. */
static int write_pfm(const char *name, const struct image *img)
{
    struct error err;
    return pfm_write(name, img, &err);
}

/* truth: the rules for a variance image (compare.h): a PFM of the compared images' size
 *   with every value >= 0; NaN and Inf are already refused by pfm_read.
 * tolerance: none; each bad file refused with a message naming it and the reason.
 * catches: a variance of another size read out of bounds, a negative variance taken
 *   (sqrt of it is NaN), -0 refused although it is >= 0. */
static void test_variance_read(struct check *t)
{
    char name[NAME_MAX_BYTES];
    temp_name(name, sizeof name, "compare", "var.pfm");
    struct image *like = image_create(3, 2), *var = image_create(3, 2);
    struct error err;
    image_set(var, 2, 1, vec3(0.5, -0.0, 0));
    CHECK(t, write_pfm(name, var) == 0);
    struct image *back = variance_read(name, like, &err);
    CHECK(t, back != NULL && image_get(back, 2, 1).x == 0.5);
    image_free(back);
    image_set(var, 2, 1, vec3(0.5, -1e-3, 0));
    CHECK(t, write_pfm(name, var) == 0);
    err.message[0] = '\0';
    CHECK(t, variance_read(name, like, &err) == NULL && strcmp(err.file, name) == 0);
    CHECK(t, strstr(err.message, "(2, 1)") && strstr(err.message, "negative variance"));
    image_free(var);
    var = image_create(2, 3);
    CHECK(t, write_pfm(name, var) == 0);
    CHECK(t, variance_read(name, like, &err) == NULL && strstr(err.message, "2x3"));
    remove(name);
    CHECK(t, variance_read(name, like, &err) == NULL && strstr(err.message, "cannot open"));
    image_free(var);
    image_free(like);
}

/* Runs "PHOTON compare args" with its output in log; the exit status. */
static int photon_compare(const char *args, const char *log)
{
    return photon_logged("compare", args, log);
}

/* The files of test_compare_command_line: an image, a variance, a negative variance. */
struct cli_files {
    char log[NAME_MAX_BYTES], image[NAME_MAX_BYTES];
    char var[NAME_MAX_BYTES], negative[NAME_MAX_BYTES];
};

static void make_cli_files(struct cli_files *files)
{
    temp_name(files->log, sizeof files->log, "compare", "compare.log");
    temp_name(files->image, sizeof files->image, "compare", "image.pfm");
    temp_name(files->var, sizeof files->var, "compare", "var.pfm");
    temp_name(files->negative, sizeof files->negative, "compare", "negative.pfm");
    struct image *img = image_create(2, 2);
    image_set(img, 1, 1, vec3(0.25, 0.5, 1));
    write_pfm(files->image, img);
    image_set(img, 0, 0, vec3(0.01, 0.01, 0.01));
    write_pfm(files->var, img);
    image_set(img, 0, 1, vec3(0, -1, 0));
    write_pfm(files->negative, img);
    image_free(img);
}

/* truth: the output contract in compare.c: without variance options the line is exactly
 *   what it always was; with one, the same line goes on with the block test's fields (one
 *   block of 2x2 pixels: m = 3 tests at alpha 0.01, critical 2.9342 by mpmath);
 *   bad options or variance files exit 2 with a message and print nothing on stdout.
 * tolerance: none; whole lines.
 * catches: the old line changed (scripts parse it), a second line, --alpha outside
 *   [1e-300, 1) or without a variance accepted (a tiny positive one reached an
 *   assertion), a negative variance file accepted. */
static void test_compare_command_line(struct check *t)
{
    struct cli_files f;
    char args[3 * NAME_MAX_BYTES + 64];
    make_cli_files(&f);
    const char *plain = "rmse=0 relmse=0 psnr=inf maxerr=0\n";
    snprintf(args, sizeof args, "%s %s", f.image, f.image);
    CHECK(t, photon_compare(args, f.log) == 0 && file_equals_text(f.log, plain));
    snprintf(args, sizeof args, "%s %s --ref-variance %s", f.image, f.image, f.var);
    CHECK(t, photon_compare(args, f.log) == 0 && file_equals_text(f.log, "rmse=0 relmse=0 psnr=inf "
          "maxerr=0 blocks_tested=1 blocks_untestable=0 test_block=16 z_critical=2.9342 "
          "worst_z=0 worst_z_block=0,0 worst_z_channel=r worst_z_reldiff=0 blocks_failed=0 "
          "failed_blocks=none consistent=yes alpha=0.01\n"));
    snprintf(args, sizeof args, "%s %s --test-variance %s --alpha 0.05", f.image, f.image,
             f.var);
    CHECK(t, photon_compare(args, f.log) == 0 && file_contains(f.log, " alpha=0.05\n"));
    snprintf(args, sizeof args, "%s %s --test-variance %s --alpha 1e-300", f.image, f.image,
             f.var); /* the smallest level (compare.c's ALPHA_MIN) */
    CHECK(t, photon_compare(args, f.log) == 0 && file_contains(f.log, " alpha=1e-300\n"));
    /* 5e-324 and 1e-310 are positive, but their per-channel levels round to 0 */
    static const char *bad_alpha[] = {"0", "1", "-0.1", "abc", "0.01x", "nan", "5e-324",
                                      "1e-310"};
    for (size_t i = 0; i < sizeof bad_alpha / sizeof bad_alpha[0]; i++) {
        snprintf(args, sizeof args, "%s %s --ref-variance %s --alpha %s", f.image, f.image,
                 f.var, bad_alpha[i]);
        CHECK(t, photon_compare(args, f.log) == 2 && file_contains(f.log, "--alpha"));
    }
    snprintf(args, sizeof args, "%s %s --block 4", f.image, f.image);
    CHECK(t, photon_compare(args, f.log) == 0 &&
             file_contains(f.log, " worst_block=0 worst_block_at=0,0 blocks="));
    CHECK(t, file_contains(f.log, " mean_ratio=1\n"));
    /* var.pfm is image.pfm plus 0.01 grey in one pixel: mean luminances 0.49295 / 4 and
     * 0.48295 / 4 (the other pixel 0.2126 0.25 + 0.7152 0.5 + 0.0722 1 = 0.48295) */
    snprintf(args, sizeof args, "%s %s --block 4", f.var, f.image);
    CHECK(t, photon_compare(args, f.log) == 0 && file_contains(f.log, " mean_ratio=1.02071\n"));
    snprintf(args, sizeof args, "%s %s --block 0", f.image, f.image);
    CHECK(t, photon_compare(args, f.log) == 2 && file_contains(f.log, "--block"));
    snprintf(args, sizeof args, "%s %s --alpha 0.05", f.image, f.image);
    CHECK(t, photon_compare(args, f.log) == 2 && file_contains(f.log, "needs --ref-variance"));
    snprintf(args, sizeof args, "%s %s --ref-variance", f.image, f.image);
    CHECK(t, photon_compare(args, f.log) == 2 && file_contains(f.log, "needs a file name"));
    snprintf(args, sizeof args, "%s %s --ref-variance %s", f.image, f.image, f.negative);
    CHECK(t, photon_compare(args, f.log) == 2 && !file_contains(f.log, "rmse=")
             && file_contains(f.log, "negative variance"));
    remove(f.negative);
    remove(f.var);
    remove(f.image);
    remove(f.log);
}

/* truth: block means worked by hand. b is all ones (luminance 1); in a, the full block at
 *   (16, 0) is 5% brighter and the partial 8 x 4 block at the bottom-right corner (32, 16)
 *   10% darker: the worst is that corner, 0.1, and 4 of the 3 x 2 blocks are within 3%.
 *   A black reference block under a lit one is infinitely wrong; equal images have no error.
 * catches: partial edge blocks skipped, rows and columns swapped, sums not divided by the
 *   partial block's own pixel count, blocks beyond the tolerance counted as within. */
static void test_worst_block(struct check *t)
{
    struct image *a = image_create(40, 20), *b = image_create(40, 20);
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 40; x++) {
            double v = x >= 16 && x < 32 && y < 16 ? 1.05 : x >= 32 && y >= 16 ? 0.9 : 1.0;
            image_set(a, x, y, vec3(v, v, v));
            image_set(b, x, y, vec3(1, 1, 1));
        }
    struct block_error w = image_worst_block(a, b, NULL, 16);
    CHECK(t, w.x0 == 32 && w.y0 == 16 && fabs(w.relative_error - 0.1) < 1e-12);
    CHECK(t, w.n_blocks == 6 && w.n_within == 4);
    CHECK(t, image_worst_block(b, b, NULL, 16).relative_error == 0);
    CHECK(t, image_worst_block(b, b, NULL, 16).n_within == 6);
    for (int y = 16; y < 20; y++)
        for (int x = 32; x < 40; x++)
            image_set(b, x, y, vec3(0, 0, 0));
    CHECK(t, isinf(image_worst_block(a, b, NULL, 16).relative_error));
    image_free(a);
    image_free(b);
}

/* truth: the standard error of a block mean of n pixels, each of variance v (all three
 *   channels alike, so the luminance's is v too), is sqrt(n v) / n: with v = (0.02 * 16)^2
 *   over a 16 x 16 block of ones it is 2%, over BLOCK_NOISE_FLOOR (1%), and the block is
 *   left out; at (0.005 * 16)^2, 0.5%, it counts. A 10%-off noisy block so drops out of the
 *   worst, and its neighbour 5% off becomes the worst.
 * catches: the standard error of a pixel taken for the block's (16 times too large), the
 *   variance summed without dividing by n^2, noisy blocks counted as within. */
static void test_noisy_blocks(struct check *t)
{
    struct image *a = image_create(32, 16), *b = image_create(32, 16);
    struct image *var = image_create(32, 16);
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 32; x++) {
            double v = x < 16 ? 1.05 : 0.9, s = x < 16 ? 0.005 * 16 : 0.02 * 16;
            image_set(a, x, y, vec3(v, v, v));
            image_set(b, x, y, vec3(1, 1, 1));
            image_set(var, x, y, vec3(s * s, s * s, s * s));
        }
    CHECK(t, !block_is_noisy(b, var, 0, 0, 16) && block_is_noisy(b, var, 16, 0, 16));
    CHECK(t, !block_is_noisy(b, NULL, 16, 0, 16));
    struct block_error w = image_worst_block(a, b, var, 16);
    CHECK(t, w.n_noisy == 1 && w.n_blocks == 1 && w.n_within == 0);
    CHECK(t, w.x0 == 0 && fabs(w.relative_error - 0.05) < 1e-12);
    w = image_worst_block(a, b, NULL, 16);
    CHECK(t, w.n_noisy == 0 && w.n_blocks == 2 && w.x0 == 16);
    image_free(var);
    image_free(a);
    image_free(b);
}

void test_compare(struct check *t)
{
    RUN_TEST(t, test_noisy_blocks);
    RUN_TEST(t, test_critical_values);
    RUN_TEST(t, test_sidak_level);
    RUN_TEST(t, test_consistent_noise);
    RUN_TEST(t, test_bias_detected);
    RUN_TEST(t, test_single_outlier);
    RUN_TEST(t, test_zero_variance);
    RUN_TEST(t, test_variance_read);
    RUN_TEST(t, test_compare_command_line);
    RUN_TEST(t, test_worst_block);
}
