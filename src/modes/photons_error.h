/*
 * modes/photons_error.h -- the error image of `--mode photons` (photons.c): each pixel's
 * bound on |pixel - truth| at a confidence c, of the noise of the photon map every pixel
 * shares and of the bias of its density estimates (ERROR.md's words).
 *
 * The map's noise. A pixel's samples all read one map, so their spread shows none of the
 * map's noise, which neighbouring pixels share. The map's photons are in PHOTON_BATCHES
 * batches by their paths' emission index (photon.h): independent maps of N / B photons
 * each, B = PHOTON_BATCHES. Each estimate is split by them (struct estimate_batches) at
 * the whole map's radius r, so the pixel's value is the mean over the batches b of
 *     y_b = e + B P_b,
 * e what its samples saw besides the photons (emission, the background), P_b the mean
 * over its samples of batch b's part of their estimates. Given r, the photons inside
 * the disc fall into the batches independently, so the y_b are B independent estimates
 * of the pixel, and their spread states the noise of the mean: 2009's passes
 * (sppm_error.h) with the batches as passes, pooled over the 5 x 5 pixels around as pt's
 * samples are (pixel_error.h), and a block's noise from the block's own batch means,
 * since the pixels share photons (the batches are 2009's passes one by one).
 *
 * The bias. Each estimate also sums its photons over the inner disc of radius r / sqrt(2)
 * (struct estimate_batches' inner), whose bias is half the disc's, so b_b = 2 (y_b -
 * y'_b) estimates y_b's, smoothed over the 5 x 5 pixels around as 2009's is
 * (sppm_error.h); B = |b~| + z_c sigma. The rim photon that --paper counts (exclude_rim 0;
 * Eq. 3 as printed, k / (k - 1) too bright) lies outside the inner disc, so b~ states twice
 * its bias. The two discs assume a bias of the second order in r: where a disc overhangs
 * a surface's edge the bias is nearer the first (one linear in r, b~ understates by 41%),
 * and light that changes within the inner disc (a caustic's lines) both discs blur alike;
 * the calibration finds both (src/modes/README.md).
 *
 * The camera samples. Every batch above sees all of the pixel's samples, so their spread
 * over the pixel (an outline, a shadow's edge) is in no y_b. It is independent of the
 * map's, so it is added to them: the samples kept in batches of consecutive ones as pt
 * keeps them (pixel_error.h), taken in pairs, B / 2 of 2 m samples each when all B are
 * full; pair b mod (B / 2)'s mean less the pairs' mean, c_b, joins y_b (and y'_b):
 *     y_b = e + c_b + B P_b,
 * whose mean over b is still the pixel (the c_b sum to 0 when all B batches are full:
 * 8, 16, 32, ... samples; with fewer, the h full pairs are taken b mod h, and with fewer
 * than two pairs, none), and whose spread is the samples' and the map's, added. Pairs,
 * since a pair of batches is stratified over the pixel twice as finely (pixel_error.h),
 * as the whole is: on area-over-floor at 16 samples, the median over 8 x 8 blocks of
 * rms(B) / rms(error) is 2.7 with pairs, 3.1 with the B batches themselves. Without the
 * samples' spread the truth missed the bound on the light's outline (rms(B) / rms(error)
 * 0.48; 1.7 with it).
 */
#ifndef PHOTON_PHOTONS_ERROR_H
#define PHOTON_PHOTONS_ERROR_H

#include <stddef.h>

#include "../photon/estimate.h"
#include "render.h"
#include "sppm_error.h"

struct photons_error {
    struct kept_window kept;         /* the window asked for, grown by SPPM_PIXEL_MARGIN  */
    struct estimate_batches sample;  /* this sample's batches, through its path weights   */
    struct estimate_batches *pixels; /* owned: per kept pixel, the sum over its samples   */
    double *sample_batches;          /* owned: per kept pixel, its samples' values in
                                        ERROR_BATCHES batches (error_batches_add())      */
    int *samples;                    /* owned: per kept pixel, the samples taken           */
};

/* Room for rs's window grown by the error image's margin in a width x height image;
 * every sum zero. The pixel loop renders the kept window, pe->kept.grown, without an
 * error image of its own. */
void photons_error_create(struct photons_error *pe, const struct render_settings *rs,
                          int width, int height);

/* Adds an estimate's batches, seen through the path weight beta, to this sample's. */
void photons_error_add_estimate(struct photons_error *pe, struct vec3 beta,
                                const struct estimate_batches *batches);

/* The sample is done, with the value kept pixel i took: it joins the pixel's batches of
 * samples, and its photons' batches the pixel's (nothing, if it did not count); the next
 * sample starts from zero. */
void photons_error_sample_taken(struct photons_error *pe, size_t i, struct vec3 value,
                                int counted);

/* The written window's error image, bias and block noise into *result, from the kept
 * window's mean image. */
void photons_error_result(const struct photons_error *pe, const struct image *kept_image,
                          struct render_result *result);

void photons_error_free(struct photons_error *pe);

#endif
