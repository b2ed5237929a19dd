/*
 * modes/ppm2008.h -- `--mode 2008`: progressive photon mapping (Hachisuka, Ogaki and
 * Jensen 2008).
 */
#ifndef PHOTON_PPM2008_H
#define PHOTON_PPM2008_H

#include <stddef.h>

#include "../base/error.h"
#include "progressive.h"
#include "render.h"

#define PPM_DEFAULT_PHOTONS_PER_PASS 100000 /* the paper's (Sec. 5)                      */
#define PPM_DEFAULT_PASSES 144              /* the fewest (by 16) that keep every 16 x 16
                                               block of both Cornell boxes within 3%
                                               (src/modes/measured.md)                   */
#define PPM_DEFAULT_ALPHA 0.7               /* the paper's (Sec. 5)                      */
#define PPM_DEFAULT_SPP 16                  /* eye rays per pixel that store hit points,
                                               fixed for the whole render (each pass adds
                                               one for the direct light and emission):
                                               edges in the photon estimate keep their
                                               aliasing; rays that meet a surface within a
                                               hit point's disc share it (ppm2008.c)      */
#define PPM_DEFAULT_FOOTPRINTS 4.0          /* default R0 in pixel footprints; the paper's
                                               "footprint of the pixel" (Sec. 4) is 1     */
#define PPM_DEFAULT_CAUSTIC_FOOTPRINTS 1.0  /* R0 of the caustic estimate, in footprints */
#define PPM_MAX_EYE_RAYS (1 << 24)          /* documented limit on pixels x spp: each eye
                                               ray may leave a hit point of ~380 bytes   */

struct hit_point;
struct progressive_estimate;

/* Sees the hit points after every pass's update (Eq. 7, 9, 12), e.g. to follow R(x) and
 * N(x) as the paper's Fig. 4 does. */
struct ppm_observer {
    void (*after_pass)(void *context, long pass, const struct hit_point *points, size_t n);
    void *context;
};

/* 2008's settings: what both progressive modes read, and the switches of 2008's own
 * departures. */
struct ppm_settings {
    struct progressive_settings progressive;
    int merge_hit_points;             /* 1: a pixel's eye rays share a hit point where
                                         they meet a surface within its disc             */
    int resample_emission;            /* 1: each pass's new eye ray adds the emission it
                                         sees; 0: only the ray tracing pass's rays do    */
    double caustic_footprints;        /* > 0: caustic photons (L S+ D) gather in an
                                         estimate of their own, R0 this many footprints;
                                         0: in the one estimate, the paper's             */
    const struct ppm_observer *observer; /* borrowed or NULL                               */
};

/* The defaults above: the paper's photons per pass and alpha, PPM_DEFAULT_PASSES passes,
 * pixel-footprint radii, direct light by light sampling, no report, no snapshot, no
 * observer. */
struct ppm_settings ppm_settings_default(void);

/* Eq. 7: N <- N + alpha M, the photons a hit point keeps after a pass. */
double ppm_accumulated_photons(double n, double m, double alpha);

/* Eq. 9: R <- R sqrt((N + alpha M) / (N + M)); R itself when M = 0. */
double ppm_reduced_radius(double r, double n, double m, double alpha);

/* Eq. 12: tau <- (tau_N + tau_M) (N + alpha M) / (N + M); tau_n_plus_m itself when M = 0. */
struct vec3 ppm_corrected_flux(struct vec3 tau_n_plus_m, double n, double m, double alpha);

/* After a pass, one estimate's tau_N + tau_M (in e->tau) and M (e->m_photons): Eq. 12,
 * Eq. 9 and Eq. 7 in turn, then M = 0 for the next pass. */
void ppm_update_estimate(struct progressive_estimate *e, double alpha);

/* Eq. 13: L = tau / (pi R^2 N_emitted); zero when R or N_emitted is zero (nothing can
 * have been found yet). */
struct vec3 ppm_radiance(struct vec3 tau, double r, double n_emitted);

/* Renders the window of rs: the ray tracing pass with rs->spp eye rays per pixel (the
 * caller keeps window pixels x spp <= PPM_MAX_EYE_RAYS), then photon passes as
 * progressive_passes() runs them, calling ps->observer after each. result.variance is
 * always NULL: the pixels of a progressive estimate are not means of independent samples.
 * With rs->error_confidence (and ps->progressive.passes >= ERROR_MIN_SPP), result.error,
 * .bias and .block_noise are the error image and what it states of blocks (ppm_error.h;
 * the window kept grows by SPPM_ERROR_MARGIN, and stats->hit_points counts its hit points
 * too); with rs->target_error the passes end once it is reached. */
struct render_result render_ppm(const struct scene *scene, const struct render_settings *rs,
                                const struct ppm_settings *ps,
                                struct render_counters *counters, struct ppm_stats *stats);

/* The first material with a glossy lobe (a specular part, Jensen 1996's f_r,s, that is not
 * an ideal mirror: Phong's and Ward's lobes, Schlick's with 0 < r < 1/2), or -1. The paper's
 * hit points sit on the first non-specular surface, so such a lobe is estimated from the
 * photons at a fixed hit point: a photon arriving near the lobe's peak lights the few hit
 * points that face it with a large f_r, a speckle that fades slowly with the passes, where
 * 2009 follows the lobe from the eye in every pass. */
int ppm_glossy_material(const struct scene *scene);

#endif
