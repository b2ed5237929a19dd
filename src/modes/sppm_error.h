/*
 * modes/sppm_error.h -- the error image of the progressive modes, `--mode 2009`
 * (sppm2009.c) and `--mode 2008` (ppm2008.c, whose pass values ppm_error.h makes): each
 * pixel's bound on |pixel - truth| at a confidence c, of the noise of its passes and of
 * the bias of its photon density estimates (ERROR.md's words). Below, 2009's pass values
 * and the rule both modes' bounds are made by; ppm_error.h, 2008's values and what its
 * passes cannot see. Both keep the pixels up to SPPM_ERROR_MARGIN beyond the window they
 * write (struct kept_window), which the rule reads, so that a crop's error image is its
 * window of the whole's.
 *
 * The pass values. A pixel's value is the mean over its n passes of
 *     y_i = e_i + P_i / c,   P_i = beta Phi_i / (pi R_i^2 M),
 * e_i what pass i's eye path saw (emission, background) and its light sample found, Phi_i
 * the f_r Phi' of the pass's photons within R_i of its hit point, M the photons a pass, c
 * the covered share of the pixel's discs: tau / (pi R^2) is the sum over the passes of
 * Phi_i / (pi R_i^2), which Eq. 12 keeps (Hachisuka, Ogaki and Jensen 2008; sppm2009.c),
 * so Eq. 13's tau / (pi R^2 N_emitted) is the mean of the P_i. A pixel keeps its y_i in
 * batches as pt keeps its samples (pixel_error.h, error_batches_add(), n the pass): the
 * passes' photons are independent, their eye paths consecutive points of the pixel's
 * stratified sequence. c is the share the image divides by when the bound is made (1
 * away from edges, corners and curved walls, and without coverage; sppm_error_add_pass()
 * says why not pass i's own).
 *
 * The bias. A density estimate over a uniform disc of radius R errs on average by about
 * (1/2) m2 Lap(L) = Lap(L) R^2 / 8 (m2 = R^2 / 4, the disc's second moment along an
 * axis; Hachisuka, Jarosz and Jensen 2010 bound progressive photon mapping's error by
 * this bias plus a noise bound, with Lap(L) from a smooth kernel's derivatives; the text
 * of the paper we could search shows no equation numbers, so the estimator below, two
 * nested discs, and its formulas are ours). Each pass also sums the f_r Phi' of its
 * photons within R_i / sqrt(2) (inner_tau), y'_i the value over that disc, of half the
 * area: its bias is Lap(L) R_i^2 / 16, so
 *     b_i = 2 (y_i - y'_i)
 * estimates y_i's (and y_i - b_i = 2 y'_i - y_i is Richardson's extrapolation to R = 0).
 * Half the area is the best split: with a share a inside, b = (y - y') / (1 - a) has a
 * variance proportional to 1 / (a (1 - a)). With the disc coverage, y'_i divides by the
 * inner disc's own covered share, from the same probes: a probe uniform on the disc
 * falls within R / sqrt(2) half the time (u < 1/2, disc_probe()), and is then uniform on
 * the inner disc, so no probe is added.
 *
 * Smoothing. A pixel's own b_i is noise twice y_i's, which would double the bound where
 * the bias is small; the bias itself, a Laplacian seen through discs a few pixels wide,
 * changes slowly from pixel to pixel. So a pixel's b~ is the mean of the b_i of the 5 x 5
 * pixels around it (SPPM_BIAS_RADIUS, inside the kept window), batch by batch, and its
 * corrected values are s_i = y_i - b~_i: the pixel = mean(s) + b~ exactly, so
 *     |pixel - truth| <= |b~| + |mean(s) - truth|,
 * and mean(s), unbiased to the second order where Lap(L) is smooth over the 5 x 5 pixels,
 * has its noise (b~'s included) bounded as pt's mean is: z_c sigma, sigma from the
 * batches of s pooled over the agreeing 5 x 5 pixels (pooled_error_image()). The bound
 * is B = |b~| + z_c sigma per channel, and b~ the bias render_result hands on. Smoothed
 * over the pool's agreeing pixels instead, b~ is noisier (a steep but smooth gradient
 * keeps the neighbours out) and the bound looser (point-over-plane 3.6 where 2.6).
 *
 * Blocks. The pixels share photons over discs a few pixels wide, so their noise is not
 * independent and a block's does not shrink as the square root of its pixels: in
 * quadrature, 0.41-0.70 of 16 x 16 blocks hold their truth. A block's noise bound is
 * from the block's own values of s, pass by pass: each pass, the block's mean of the
 * pass's s_i joins its BLOCK_BATCHES batches (error_batches_add(); sppm_error_pass_done()),
 * whose k full ones (16 <= k <= 32 from 16 passes on) state the noise at Student's t for
 * k - 1 degrees of freedom: 2.13-2.04 at c = 0.95, where a pixel's 4 to 8 batches would
 * need 3.18-2.36. Its shares are 1, since the image's are known only at its end, so the
 * spread is scaled by the ratio of two spreads of the block's values of s from the
 * pixels' batches: with the image's shares and with 1 (the ratio is 1 where every share
 * is 1). A block's bias is the mean of the b~ of its pixels and of those up to
 * BLOCK_BIAS_REACH (one block) beyond it each side, inside the image: 48 x 48 pixels
 * where it has neighbours all round; so is its pass's s the block's mean of y_i less
 * that mean of the pass's b~_i. Its own pixels' b~ alone would be mostly noise where the
 * bias is small, and paid for twice, in |b| and again in the noise of s, which carries
 * it: on the Cornell box (2009's defaults, seed 7, against the pt reference) a block's
 * bound was 4.5 times its error at the median, its bias part 0.7 times and its noise
 * part 4.0 times, where the noise of the y_i alone would state 3.2. Over its reach, the
 * block's bias has a ninth of that noise, and where the light is smooth it is the same
 * Laplacian seen through discs a few pixels wide. Where it is not (a caustic beside a
 * quiet block, a sphere flake's small spheres), the reach would carry a neighbour's bias
 * into the quiet block, or spread the caustic's own over its neighbours: so a block
 * keeps its own bias and s where d, its own b~'s mean less its reach's, lies further
 * from 0 than t times d's standard error, from the same 32 batches (keeps_own_bias()).
 * A crop keeps the reach and the smoothing around it (SPPM_ERROR_MARGIN), so that a block
 * it holds whole is stated as in the whole image. `--mode photons` keeps each block's own
 * (a reach of 0): its fixed disc of 100 photons leaves a bias large against its noise
 * and changing at that disc's scale, where the reach let the truth out of more blocks of
 * ppm-box (0.949 of 256 within the bound, 0.902 with it) and cardioid-ring (0.842,
 * 0.718). 32 batches, not more: a pass's eye paths and light samples are stratified
 * over the passes (pixel_error.h), so batches of fewer passes overstate that noise,
 * which is most of it where the direct light is by light samples: 2008 at its defaults
 * on point-over-plane, 64 passes, states its blocks at 19 times their error with 32
 * batches, 36 with 64 and 14 with a pixel's 8.
 *
 * Measured with seed 7 against the scenes' references (make calibration's cells, at
 * the defaults): the share of blocks within their bound and the median of bound /
 * error, with each block's own bias, with the reach's everywhere, and as above:
 *     2009, Cornell box        0.981 at 4.65   0.973 at 3.74   0.977 at 3.98
 *     2009, mirror-caustic     0.975 at 6.34   0.975 at 4.41   0.975 at 6.34
 *     2008, Cornell box        0.996 at 5.31   0.977 at 3.84   0.977 at 4.11
 *     2008, mirror-caustic     0.975 at 3.28   0.900 at 2.95   0.925 at 2.95
 * (mirror-caustic has 40 blocks; a true 95% bound leaves 4 of them out once in 7). With
 * the reach everywhere, --target-error 0.02 took 2009 on mirror-caustic to 120 CPU
 * seconds with 38 of 40 blocks, where each block's own took 37 s and 896 passes (as
 * above: 34 s, 896 passes), and brought 59 of sphereflake's 256 blocks within it in 120
 * s where 79 (as above: 59 too); on the Cornell box 252 where 241 (as above: 249).
 * --target-error 0.05 on sky-over-floor at 64 x 48 stops at 88 passes, where it took
 * 104 with each block's own bias and 416 with its pixels' noise in quadrature.
 *
 * Measured (tests/test_error_2009.c prints them; 20,000 photons a pass, the direct light
 * from the photons, the paper's way, so that the density estimate carries the light the
 * closed form knows): the truth within the 95% bound in 0.95-0.99 of the pixels and
 * channels of point-over-plane at 32 x 32 (64 and 256 passes), sky-over-floor and
 * area-over-floor (seeds 11-14, 21-26, 31-38, 41-44, 301-304), 0.83-0.93 without the
 * bias term on point-over-plane, 0.91-0.94 on area-over-floor, 0.96-0.99 on
 * sky-over-floor, whose soft shadow is nearly flat; the median over 8 x 8 blocks of
 * rms(B) / rms(error) 2.0-3.0, up to 3.3 on sky-over-floor at 64 passes of 48 x 36, where
 * the bias is small and b~'s noise adds to both terms. Richardson's values 2 y'_i - y_i in place of s_i
 * (b unsmoothed) cover 0.998-1.000 at 4.4-7.0 times the error; each pixel's own b_i, 2.7-4.2.
 * Where the disc is not small against the light's changes the expansion fails:
 * point-over-plane at 24 x 24, R0 = 4 footprints = 0.58 of the light's height, 0.90-0.91.
 * With the direct light by light samples (the default) the light samples and eye paths
 * are stratified over the passes, whose mean then errs far less than the batches' spread
 * says: point-over-plane covered 1.000 at 5.8 times the error.
 */
#ifndef PHOTON_SPPM_ERROR_H
#define PHOTON_SPPM_ERROR_H

#include <stddef.h>
#include <stdint.h>

#include "../base/vec3.h"
#include "../image/error_image.h"
#include "../image/image.h"
#include "../photon/hit_points.h"

#include "pixel_error.h"
#include "render.h"

#define SPPM_BIAS_RADIUS 2         /* pixels each side whose bias a pixel's b~ averages   */
#define BLOCK_BATCHES 32           /* the batches a block's pass values are kept in       */
#define BLOCK_BIAS_REACH ERROR_BLOCK /* pixels each side whose b~ 2008's and 2009's blocks'
                                        bias averages                                  */
/* The pixels beyond a window its error image reads: the pool of pixel_error.h around
 * each pixel and the bias of SPPM_BIAS_RADIUS around each of those (`--mode photons`);
 * with the b~ of BLOCK_BIAS_REACH around each block, which takes in that pool, the bias
 * of SPPM_BIAS_RADIUS around each of those (2008, 2009). */
#define SPPM_PIXEL_MARGIN (ERROR_POOL_RADIUS + SPPM_BIAS_RADIUS)
#define SPPM_ERROR_MARGIN (BLOCK_BIAS_REACH + SPPM_BIAS_RADIUS)
#define NOT_WRITTEN ((size_t)-1)   /* a kept pixel outside the written window             */

/* The window a progressive mode keeps: the one asked for, grown by a margin each side
 * (inside the image; SPPM_ERROR_MARGIN with an error image, else 0), whose pixels' pass
 * values the bound of a pixel near the written window's edge reads, so that a crop's
 * error image is its window of the whole's. Only the asked window is written. */
struct kept_window {
    const struct render_settings *asked; /* borrowed: the window written              */
    struct render_settings grown;        /* asked's settings, the window grown         */
    int width, height;                   /* of the kept (grown) window                 */
    int out_x0, out_y0;                  /* the written window within the kept one ... */
    int out_width, out_height;           /* ... and its size                           */
};

/* asked's window grown by margin pixels each side, inside an image_width x image_height
 * image. */
void kept_window_init(struct kept_window *k, const struct render_settings *asked,
                      int image_width, int image_height, int margin);

/* Pixel `written` (row-major) of the written window, as an index of the kept one. */
size_t kept_pixel(const struct kept_window *k, size_t written);

/* Kept pixel `kept`'s index in the written window, or NOT_WRITTEN. */
size_t written_pixel(const struct kept_window *k, size_t kept);

/* What a progressive mode keeps for its error image: per pixel of the kept window, and
 * per block of the written one. */
struct sppm_error {
    int width, height;      /* of the window kept                                          */
    int x0, y0, x1, y1;     /* the written window [x0, x1) x [y0, y1) of the kept one, ... */
    int wx0, wy0;           /* ... whose top left pixel is (wx0, wy0) of the whole image   */
    int columns, rows;      /* its blocks (error_block_grid())                             */
    int block_bias_reach;   /* the pixels each side of a block whose b~ its bias averages:
                               BLOCK_BIAS_REACH (2008, 2009), or 0 (photons)              */
    double *pass_batches;   /* owned: the batches of the pass values (error_batches_add(),
                               n = the pass), batch by batch, 9 a pixel in each: e_i, P_i
                               and the inner disc's P'_i, as pass_values                  */
    double *shares;         /* owned: 2 per pixel, the covered shares c and c' the image
                               divides P and P' by, as they stand (1 without coverage)    */
    struct vec3 *before;    /* owned: per pixel, what its eye paths saw and its direct term
                               summed before this pass                                    */
    double *pass_values;    /* owned: 9 per pixel, this pass's e_i, P_i and P'_i           */
    double *pass_scratch;   /* owned: 6 per pixel, this pass's b_i (then y_i) and b~_i       */
    double *block_batches;  /* owned: 3 BLOCK_BATCHES per block, the batches of the block's
                               mean of s_i with every share 1 (sppm_error_pass_done())   */
};

/* Room for kept's window and the blocks of the window it writes, every sum zero; a
 * block's bias is the mean of the b~ of its pixels and of those up to block_bias_reach
 * beyond it (which kept's margin must hold: SPPM_ERROR_MARGIN for BLOCK_BIAS_REACH,
 * SPPM_PIXEL_MARGIN for 0). */
void sppm_error_create(struct sppm_error *e, const struct kept_window *kept,
                       int block_bias_reach);

/* This pass's values of pixel i: what its eye path saw and its direct term, e_i, and
 * its photon estimate over the disc and over the inner disc, P_i and P'_i, before the
 * covered shares divide them. Kept apart, so that y_i = e_i + P_i / c and y'_i = e_i +
 * P'_i / c' are formed with the shares c, c' the image itself ends with (shares), not
 * those of pass i: a share estimated from the probes so far swings over the first passes
 * (one probe a pass), and where a disc is half covered (a sphere curving away from it)
 * those passes' values stated bounds of 23% on the furnace, whose image is within 0.2%. */
void sppm_error_add_pass(struct sppm_error *e, size_t i, struct vec3 seen, struct vec3 p,
                         struct vec3 p_inner);

/* Pass `pass` (from 0) is done, every pixel's values added (sppm_error_add_pass()): they
 * join the pixels' batches, and each block's mean of the pass's corrected values s_i,
 * every share taken as 1, joins the block's BLOCK_BATCHES batches (above). */
void sppm_error_pass_done(struct sppm_error *e, long pass);

/* A progressive estimate's part of a pass value, seen through weight (the hit point's
 * pixel weight, 2009's path weight): *p = weight Phi_i / (pi R_i^2 M) over its disc of
 * radius R_i, and *p_inner = weight 2 Phi'_i / (pi R_i^2 M) over its inner disc of radius
 * R_i / sqrt(2), Phi_i and Phi'_i the f_r Phi' the pass's photons gave the two (tau and
 * inner_tau; hit_point_add_photon()); both zero for a radius too small to hold a photon
 * (ppm_radiance()'s rule). */
void sppm_error_photons(struct vec3 weight, double radius, struct vec3 tau,
                        struct vec3 inner_tau, double photons_per_pass, struct vec3 *p,
                        struct vec3 *p_inner);

/* The error image of the written window after `passes` passes (>= ERROR_MIN_SPP) at
 * confidence c, by the rule above, which reads the pixels up to SPPM_ERROR_MARGIN beyond
 * it; *bias: their b~, *block: the noise bound of each block's mean, *block_biases: its
 * bias (render_result's bias, block_noise and block_bias). */
struct image *sppm_error_image(const struct sppm_error *e, long passes, double confidence,
                               struct image **bias, struct image **block,
                               struct image **block_biases);

/* The written window's error image, bias and block noise after `passes` passes, at the
 * kept settings' confidence, into result. */
void sppm_error_result(const struct sppm_error *e, const struct kept_window *k, long passes,
                       struct render_result *result);

/* --target-error's judgement (progressive.h) of mean, the written window's image after
 * `passes` passes, by its error image: target_tally() against the asked settings. */
int sppm_error_target(const struct sppm_error *e, const struct kept_window *k, long passes,
                      const struct image *mean, struct render_counters *counters);

void sppm_error_free(struct sppm_error *e);

#endif
