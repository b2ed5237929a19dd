/*
 * modes/pixel_error.h -- the error image of a mode whose pixels are means of independent
 * samples (pt): each pixel's bound on |pixel - truth| at a confidence c, from the spread
 * of its samples and its neighbours'.
 *
 * Batch means. A pixel keeps its samples in ERROR_BATCHES batches of m consecutive ones,
 * m the least power of two with ERROR_BATCHES m >= n (error_batches_add()). Its mean of n
 * samples has the variance s^2 / n, where s^2, the variance of one sample's worth, is
 * estimated from the spread of the k = n / m full batches' means times m. Batches, not
 * single samples, because the camera points are stratified (render.h): a batch of m
 * consecutive points of the (0,2)-sequence is itself stratified over the pixel, so the
 * batches' spread sees the stratified estimate's error, which on a sharp outline falls
 * far faster than independent samples' would (on area-over-floor's light at 64 samples
 * the bound from single samples is 4.7 times the error's rms, from 16 batches 2.8, from
 * 8 batches 2.5); the whole mean, a finer stratification still, errs no more than the
 * batches say. Fewer batches are tighter on outlines but each pixel's own spread is then
 * noisier: 8 (4 to 8 full ones) is the count the figures below were measured at.
 *
 * Pooling. Estimated from the pixel's own samples alone, s^2 is unbiased but mostly too small
 * where rare samples carry much of the light (a sphere hiding a sliver of the sky, a
 * small light found by a bounce): most pixels never draw one, state a small spread and
 * miss the truth. Neighbouring pixels draw from nearly the same distribution, so the
 * bound takes the larger of the pixel's own s^2 and the pooled s^2 of the pixels within
 * ERROR_POOL_RADIUS of it (5 x 5; each weighted by its k - 1 degrees of freedom), which
 * has seen the rare samples up to 25 times as often; the larger, so that a pixel on an
 * edge, noisier than its neighbours, keeps its own. A neighbour joins the pool only if
 * its mean agrees with the pixel's, within POOL_AGREEMENT_Z standard errors of their
 * difference, so that a pixel inside a light seen directly (every sample the same) does
 * not take the spread of the light's outline. The bound is then
 *     B = z_c sqrt(max(s^2_own, s^2_pooled) / n),   z_c: P(|Z| <= z_c) = c,
 * a normal quantile: the pooled spread has at least 27 degrees of freedom (k - 1 >= 3 a
 * pixel, 9 pixels in an image's corner) and mostly 175, where Student's t exceeds the
 * normal by 5% and 0.6%. Measured at c = 0.95 against closed forms (tests/test_error.c
 * prints them): on scenes/analytic/sky-over-floor.scene the truth within B in 0.99, 0.98
 * and 0.97 of the floor's pixels at 16, 64 and 256 samples, rms(B) / rms(error) 2.2-2.3
 * (an exact bound gives 1.96); the pixel's own s^2 alone gives 0.57, 0.83 and 0.93,
 * pooling over 3 x 3 pixels 0.95, 0.98 and 0.97, the pooled s^2 alone without the own
 * 0.96, 0.95 and 0.96. On area-over-floor.scene 0.97 at 16 and 64 samples; its light's
 * outline makes rms(B) / rms(error) 4.2 there at 16 samples (2.5 at 64), 2.2-2.4 the
 * median over 8 x 8 blocks. Below
 * ERROR_MIN_SPP samples even the pooled spread misses the rare values (0.89 at 4
 * samples), so the command line asks for at least that many.
 *
 * Pixels near the window's edge pool from the pixels beyond it, which the render
 * samples for that alone (render.c), so a crop's error image is the same window of the
 * whole image's; the image's own edges pool over the pixels there are.
 */
#ifndef PHOTON_PIXEL_ERROR_H
#define PHOTON_PIXEL_ERROR_H

#include "../image/image.h"

#define ERROR_POOL_RADIUS 2 /* pixels each side whose samples a pixel's spread pools     */
#define ERROR_MIN_SPP 16    /* samples a pixel needs for an error image (above)            */
#define ERROR_BATCHES 8     /* the batches a pixel's samples are kept in (above)            */
#define POOL_AGREEMENT_Z 3  /* a neighbour joins the pool when its mean and the pixel's
                               differ by at most this many standard errors of the
                               difference (above)                                          */

/* The samples of one of `count` batches once n are taken: the least power of two m with
 * count m >= n (n / m of the batches are full). A pixel's batches are ERROR_BATCHES. */
int error_batch_size(int count, int n);

/* Adds sample v (`width` values: 3, one per channel) to `count` batch sums of `width`
 * values each (zero before the first sample), after the n taken: the batches of m samples
 * (above) in sample order, m doubling, and pairs of batches becoming one, whenever every
 * batch is full. Many pixels whose samples are taken together (2009's passes) are one
 * sample of as many values: their batches then lie batch by batch, each a stretch of
 * memory that an add reads from start to end. */
void error_batches_add(double *batches, int count, int n, const double *v, size_t width);

/* The sums of a window of pixels: width x height, row-major, 3 per pixel for sum (the
 * samples' sum per channel) and 3 ERROR_BATCHES for batches (error_batches_add()), n the
 * samples of each. */
struct pixel_sums {
    int width, height;
    const double *sum, *batches; /* borrowed */
    const int *n;                /* borrowed */
};

/* The error image of the pixels [x0, x1) x [y0, y1) of the sums' window, at confidence c
 * (0 < c < 1), by the rule above. A pixel with n < 2 whose pool holds no pixel of n >= 2
 * has no spread to state: the caller guarantees n >= 2 everywhere (asserted). */
struct image *pooled_error_image(const struct pixel_sums *sums, int x0, int y0, int x1, int y1,
                                 double confidence);

/* For each pixel of the sums' window and each channel, the mean over its pool (the
 * pixels within ERROR_POOL_RADIUS whose means agree with its own, as pooled_error_image()
 * pools their spreads) of another series' batches, batches (3 ERROR_BATCHES per pixel,
 * kept as the sums' are: the same n), into pooled (as many). */
void pooled_batch_means(const struct pixel_sums *sums, const double *batches, double *pooled);

#endif
