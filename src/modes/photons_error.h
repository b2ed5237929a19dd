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
 * since the pixels share photons.
 *
 * The bias. Each estimate also sums its photons over the inner disc of radius r / sqrt(2)
 * (struct estimate_batches' inner), whose bias is half the disc's, so b_b = 2 (y_b -
 * y'_b) estimates y_b's, smoothed over the 5 x 5 pixels around as 2009's is
 * (sppm_error.h); B = |b~| + z_c sigma. The rim photon that --paper's count_rim adds (Eq.
 * 3 as printed, k / (k - 1) too bright) lies outside the inner disc, so b~ states twice
 * its bias.
 *
 * Not stated: the camera samples' spread over the pixel (every batch sees the same
 * samples), as 2008's bound does not state its fixed eye rays' (ppm_error.h): the
 * samples are stratified over the pixel, and the estimate is smooth over a disc wider
 * than a pixel; the calibration (reference/suite.md) measures what that leaves out.
 */
#ifndef PHOTON_PHOTONS_ERROR_H
#define PHOTON_PHOTONS_ERROR_H

#include <stddef.h>

#include "../photon/estimate.h"
#include "render.h"
#include "sppm_error.h"

struct photons_error {
    struct kept_window kept;         /* the window asked for, grown by SPPM_ERROR_MARGIN  */
    struct estimate_batches sample;  /* this sample's batches, through its path weights   */
    struct estimate_batches *pixels; /* owned: per kept pixel, the sum over its samples   */
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

/* The sample is done: its batches join kept pixel i's (nothing, if it did not count),
 * and the next sample starts from zero. */
void photons_error_sample_taken(struct photons_error *pe, size_t i, int counted);

/* The written window's error image, bias and block noise into *result, from the kept
 * window's mean image. */
void photons_error_result(const struct photons_error *pe, const struct image *kept_image,
                          struct render_result *result);

void photons_error_free(struct photons_error *pe);

#endif
