/*
 * modes/photons.h -- `--mode photons`: the global photon map seen directly, as Jensen
 * 1996's Fig. 4 ("the radiance estimate from the global photon map").
 */
#ifndef PHOTON_PHOTONS_H
#define PHOTON_PHOTONS_H

#include <stddef.h>

#include "../base/error.h"
#include "../photon/global_work.h"
#include "render.h"

#define PHOTONS_DEFAULT_N 200000   /* --photons: photons emitted for the global map     */
#define PHOTONS_DEFAULT_GATHER 100 /* --gather: photons in each radiance estimate       */
#define MAX_GATHER 100000          /* documented limit on --gather: the scratch holds
                                      this many pointers and distances (1.6 MB)          */
#define PHOTONS_RADIUS_FRACTION 0.1 /* default maximum radius: this fraction of the
                                       diagonal of the scene's bounding box (the papers
                                       have none: src/modes/README.md, Estimates)       */
#define CAUSTIC_RADIUS_FRACTION 0.25 /* caustic estimates (1994, 1996) reach this much of
                                        the maximum radius by default (--caustic-radius-
                                        fraction): caustic photons are dense where they
                                        are, and a wide disc hangs over the edges of the
                                        surface where they are sparse                   */

/* The largest radius of an estimate from a mode's max_radius setting: itself when > 0;
 * none (HUGE_VAL) when 0, the papers' sphere, grown until it holds its photons
 * (--no-max-radius); else the default, PHOTONS_RADIUS_FRACTION of diagonal. */
double largest_radius(double max_radius, double diagonal);

/* The squared maximum radii of modes 1994's and 1996's photon estimates: every
 * estimate's, largest_radius() of the scene's diagonal (scene_diagonal(): 1 for a scene
 * with no extent), and the caustic estimates', caustic_fraction of that radius. One
 * set-up, so --max-radius and --caustic-radius-fraction mean the same in both modes.
 * (`--mode photons` sets its own radius up: no limit at all for a scene with no
 * extent.) */
struct max_radii {
    double all_r2;     /* every estimate's, or the global map's                         */
    double caustic_r2; /* the caustic estimates': all_r2 times the fraction squared     */
};
struct max_radii max_radii_of(double max_radius, double caustic_fraction, double diagonal);

struct photon_settings {
    size_t n_photons;  /* N emitted, 1..MAX_PHOTONS (trace.h)                           */
    size_t gather;     /* k, photons per estimate, 1..MAX_GATHER                        */
    double max_radius; /* > 0: photons farther than this are not gathered; 0: none,
                          the paper's; < 0: the default, largest_radius()               */
    double cone_k;     /* 0: the plain estimate; >= 1: the cone filter (estimate.h)     */
    int exclude_rim;   /* 1: the rim photon only marks r (a departure); 0: it counts,
                          as Eq. 3 is printed (the paper's; estimate.h)                 */
    struct global_work *work; /* NULL: the map is traced and released here; else, empty,
                                 it receives the map (maps[0]), or, full, holds the map
                                 to use instead of tracing one (photon/global_work.h)  */
};

/* What the photon pass did, for --stats. */
struct photon_stats {
    size_t photons_emitted;         /* N                                                */
    size_t photons_stored;          /* photons in the map                               */
    double bytes_per_photon;        /* the map's bytes (kdtree_bytes) per stored photon */
    double seconds_photons;         /* CPU seconds tracing photons                      */
    double seconds_balance;         /* CPU seconds balancing the kd-tree                */
    double max_radius;              /* the maximum gathering radius used                */
    unsigned long long photon_rays; /* rays cast tracing photons (render_counters.rays
                                       counts the camera pass's only)                  */
};

/* Traces the global map (every diffuse hit: direct, caustic and indirect photons; seed
 * rs->seed, pass 0, rs->max_depth bounces), balances it, and renders the window of rs
 * through render_pixels(): camera rays follow delta lobes (mirror, glass) up to
 * rs->max_depth, and at a surface with a non-delta part the pixel takes its emission
 * plus the radiance estimate from the ps->gather nearest photons. result.seconds and the
 * checkpoints' seconds include the photon pass. On failure (more than MAX_PHOTONS
 * photons would be stored, or ps->work holds what is not one map) returns a result with
 * image NULL and *err filled. */
struct render_result render_photons(const struct scene *scene, const struct render_settings *rs,
                                    const struct photon_settings *ps, int want_variance,
                                    const struct checkpoint *checkpoint,
                                    struct render_counters *counters, struct photon_stats *stats,
                                    struct error *err);

#endif
