/*
 * modes/ppm_error.h -- the error image of `--mode 2008` (ppm2008.c): each pixel's pass
 * values, kept as 2009 keeps its own (sppm_error.h, whose batches, bias, pools and blocks
 * make the bound), and what 2008's hit points add to them.
 *
 * The pass values. A pixel's value is the mean over the passes of
 *     y_i = e_i + d_i + sum over its hit points of w (P_i + C_i),
 * e_i the emission and background pass i's new eye ray saw, d_i what its light samples
 * took, w the hit point's pixel weight, and P_i = Phi_i / (pi R_i^2 M) the pass's share
 * of the global estimate's Eq. 13, C_i the caustic estimate's (Hachisuka, Ogaki and
 * Jensen 2008): Phi_i is the pass's tau_M (Eq. 10-11, the f_r Phi' of its photons within
 * R_i), which Eq. 12 adds to tau and scales by (N + alpha M) / (N + M), as Eq. 9 scales
 * R^2 (N from Eq. 7), so each estimate's tau / (pi R^2) is the sum over the passes of
 * Phi_i / (pi R_i^2) whatever N and R do, and Eq. 13's tau / (pi R^2 N_emitted),
 * N_emitted = n M, is the mean of the Phi_i / (pi R_i^2 M). tau_M is read as tau less its
 * value after the last update (ppm_error_end_pass()), so the photon loop only sums the
 * inner discs. The emission part of the image is the mean over all the pixel's eye rays,
 * the --spp of the ray tracing pass and the passes' (ppm2008.c), a finer stratification
 * of the same camera points than the passes' alone, which err no less than their batches
 * say; with --no-resample-emission (refused) it would be the --spp rays' alone, fixed.
 *
 * The bias, as 2009's: each estimate of each hit point also sums the f_r Phi' of the
 * pass's photons within R_i / sqrt(2) (hit_point_add_photon(); a caustic estimate with
 * members, by the share of them whose inner discs hold the photon), y'_i the value over
 * those discs of half the area, b_i = 2 (y_i - y'_i), smoothed over 5 x 5 pixels.
 *
 * What the passes cannot see. 2008's hit points are made once, by the ray tracing pass:
 * the photon estimate of a pixel is the mean over its --spp fixed points (one merged hit
 * point standing for several), not over its square, and no number of passes re-samples
 * them, so the spread of the passes states none of that aliasing. By default it is small
 * against the bound: with the direct light by light samples the hit points carry only
 * the photons' light after a bounce, smooth over a disc several pixels wide. Where the
 * photons bring the direct light (--no-direct-light-samples, --paper) the hit points
 * carry the light's whole gradient and edges, a merged hit point one point of it for the
 * pixel; and with the emission seen by the fixed rays alone (--no-resample-emission) a
 * light's outline: option_checks.c (check_error_2008()) says what the bound did there
 * against closed forms, and refuses both.
 */
#ifndef PHOTON_PPM_ERROR_H
#define PHOTON_PPM_ERROR_H

#include <stddef.h>

#include "../photon/hit_points.h"
#include "ppm_direct.h"
#include "sppm_error.h"

/* What 2008 keeps for its error image. */
struct ppm_error {
    const struct kept_window *kept; /* borrowed: the window kept and the one written     */
    struct sppm_error values; /* the pass values' batches, per pixel of the kept window  */
    struct vec3 *inner;       /* owned: 2 per hit point (in the tree's order), the f_r Phi'
                                 this pass's photons gave the inner discs of its global
                                 and caustic estimates (hit_point_add_photon())        */
    struct vec3 *tau_before;  /* owned: 2 per hit point, its estimates' tau after the last
                                 update, which the pass's tau_M is added to            */
    struct vec3 *y, *y_inner; /* owned: per pixel, the pass's P_i and P'_i being summed  */
    long passes;              /* passes added                                           */
};

/* Room for the pixels of kept and n_points hit points, after the ray tracing pass, whose
 * emission seen (emission_seen, per kept pixel, as direct's sums; direct NULL when the
 * photons bring the direct light) is no pass's. */
void ppm_error_create(struct ppm_error *e, const struct kept_window *kept, size_t n_points,
                      const struct vec3 *emission_seen, const struct ppm_direct *direct);

/* A pass after its photons and its eye rays, before the update: every pixel's y_i and
 * y'_i (above) from the emission seen and the direct term's sums so far and the hit
 * points of tree (summed in the order they were made, so that a pixel's values do not
 * depend on the window), M = photons_per_pass; then the inner sums are cleared. */
void ppm_error_add_pass(struct ppm_error *e, const struct hit_point_tree *tree,
                        double photons_per_pass, const struct vec3 *emission_seen,
                        const struct ppm_direct *direct);

/* After the update (Eq. 12 has scaled tau): each estimate's tau, which the next pass's
 * tau_M adds to. */
void ppm_error_end_pass(struct ppm_error *e, const struct hit_point_tree *tree);

/* --target-error's judgement of mean, the written window's image so far
 * (sppm_error_target()). */
int ppm_error_target(const struct ppm_error *e, const struct image *mean,
                     struct render_counters *counters);

/* The written window's error image, bias and block noise into result, and e freed;
 * returns the CPU seconds it took. */
double ppm_error_finish(struct ppm_error *e, struct render_result *result);

#endif
