/*
 * modes/jensen1996_settings.h -- the settings of `--mode 1996`, their defaults
 * (jensen1996_settings.c), and the figures the render reports for --stats.
 *
 * A header of its own because both passes read them: pass 1 (jensen1996_maps.h) and the
 * render that calls it (jensen1996.h) take them from here, so neither includes the other.
 */
#ifndef PHOTON_JENSEN1996_SETTINGS_H
#define PHOTON_JENSEN1996_SETTINGS_H

#include <stddef.h>

#include "../photon/global_work.h"
#include "render.h"

#define J96_DEFAULT_PHOTONS 1250000        /* --photons: enough, with --disc-coverage and
                                              k = 40, for every block of both Cornell
                                              boxes to be within 3%: fewer leave the
                                              specular box's ceiling, which sees the
                                              floor's caustics through the global map's
                                              few caustic photons, past it, and more cost
                                              memory (src/modes/measured.md)              */
#define J96_DEFAULT_GATHER 40              /* --gather: k of the global map's estimates;
                                              a smaller disc blurs the crease under the
                                              front ball less (src/modes/measured.md)     */
#define J96_DEFAULT_SPP 128                /* --spp: the final pass costs little beside
                                              the maps and the cache all samples share,
                                              so 64 more samples than 64 cut the camera's
                                              noise for a small part of the time
                                              (src/modes/measured.md)                     */
#define J96_DEFAULT_CAUSTIC_PHOTONS 1000000 /* --caustic-photons: enough that the glass
                                               ball's caustic keeps its edges
                                               (src/modes/measured.md)                    */
#define J96_DEFAULT_CAUSTIC_GATHER 60      /* photons in a caustic estimate               */
#define J96_DEFAULT_GATHER_RAYS 512        /* --gather-rays: final gather rays per
                                              record; with fewer, a record's own noise
                                              shows as a bright patch beside the glass
                                              ball (src/modes/measured.md)                */
#define J96_DEFAULT_GLOSSY_RAYS 6          /* --glossy-rays: the paper's "maximum of 6"   */
#define J96_DEFAULT_CACHE_ACCURACY 0.15    /* --cache-accuracy: Ward's a                  */
#define J96_DEFAULT_ACCURATE_DISTANCE 3.0  /* --accurate-distance (see jensen1996.c): at
                                              3 radii, more short gather rays into a
                                              crease take the map's indirect photons
                                              alone, which blurs the crease under the
                                              Cornell box's front ball less than 1 does,
                                              at no cost in time (src/modes/measured.md)  */
#define J96_DEFAULT_ACCURATE_WEIGHT 0.1    /* --accurate-weight (see jensen1996.c)        */
#define J96_DEFAULT_PRECOMPUTED 16         /* --precomputed-irradiance: records at every
                                              16th photon of the global map (Christensen
                                              1999 took every 4th: the same blocks for
                                              more precomputation; sparser records leave
                                              many more gather rays' ends without one
                                              near enough; src/modes/README.md)           */
#define J96_MAX_PRECOMPUTED 1000000        /* documented limit on --precomputed-irradiance */
#define J96_VISIBILITY_PHOTONS 16          /* photons that decide a light's visibility    */
#define J96_MAX_GATHER_RAYS 65536          /* documented limit on --gather-rays           */

struct jensen1996_settings {
    size_t global_photons;    /* photons emitted for the global map, 1..MAX_PHOTONS       */
    size_t caustic_photons;   /* photons emitted towards specular objects; 0: no caustic
                                 map (caustics are then missing from the image)          */
    size_t global_gather;     /* k of the global map's estimates, 1..MAX_GATHER          */
    size_t caustic_gather;    /* k of the caustic map's estimates, 1..MAX_GATHER         */
    double max_radius;        /* > 0: the global estimates' largest radius; 0: none,
                                 the paper's; < 0: the photons mode's default (1/10 of
                                 the scene's diagonal), a departure (photons.h)          */
    double caustic_radius_fraction; /* caustic estimates reach this fraction of it, in
                                 (0, 1] (CAUSTIC_RADIUS_FRACTION)                        */
    double cone_k;            /* cone filter of the caustic estimate (Eq. 4-5); 0: none */
    int exclude_rim;          /* 1: estimates leave out the rim photon (a departure);
                                 0: count it, as Eq. 3 is printed (the paper's)          */
    int gather_rays;          /* rays of one final gather, 2..J96_MAX_GATHER_RAYS        */
    int glossy_rays;          /* rays sampling a glossy specular part at an accurate
                                 point, 1..1000                                          */
    double cache_accuracy;    /* Ward's a, > 0; 0 turns the irradiance cache off: every
                                 accurate Lambertian point gathers                       */
    double accurate_distance; /* a gather ray shorter than this many radii of the global
                                 estimate at its end gets the corner evaluation (>= 0)   */
    double accurate_weight;   /* a ray whose throughput falls below this is evaluated
                                 approximately, in [0, 1]                                */
    int shadow_rays;          /* 1: a shadow ray every time, no shadow photons (the
                                 default, a departure: jensen1996.c); 0: decide visibility
                                 from shadow photons where they agree (Jensen &
                                 Christensen 1995, the paper's)                          */
    int one_map;              /* 1: one global map of global + caustic photons, caustics
                                 from its caustic photons (the comparison of Sec. 3)     */
    int precomputed_irradiance; /* N >= 1: irradiance precomputed at every N-th photon of
                                 the global map, read where gather rays end on Lambertian
                                 surfaces (Christensen 1999; a departure, jensen1996.c);
                                 0: the paper's radiance estimate at every ray's end,
                                 0..J96_MAX_PRECOMPUTED                                  */
    int both_lobes;           /* 1: a mirror or glass at an accurate point traces both its
                                 reflected and refracted rays (Whitted's way, a
                                 departure); 0: one, sampled by the BRDF (4.2's Monte
                                 Carlo, the paper's)                                     */
    int glossy_corner;        /* 1: a surface seen through a glossy lobe is evaluated
                                 through gloss (a departure); 0: accurately, as one
                                 seen "via a few specular reflections" (the paper's)     */
    int corner_photons;       /* 1: a corner's (the end of a short gather ray's) soft
                                 indirect light from the global map's indirect photons
                                 (a departure, jensen1996_evaluation.c); 0: a final
                                 gather, as accurate points do (the paper's)             */
    int bounded_reach;        /* 1: cache records' R bounded from the camera's view
                                 (record_radius_bounds(), a departure); 0: Ward's R     */
    int gradient_limit;       /* 1: a record's R at most E / |grad E| (a departure)      */
    int disc_coverage;        /* 1: a record's estimate takes the photons of its disc's
                                 plane over the part of the disc a surface covers
                                 (photon/disc_coverage.h; a departure, jensen1996.c);
                                 0: Eq. 3's k nearest over pi r^2                        */
    const struct checkpoint *report; /* borrowed or NULL: rows after 1, 2, 4, ... samples
                                 per pixel, work = photons emitted + gather rays so far   */
    struct global_work *work; /* NULL: pass 1 and the cache's pre-pass run and are released
                                 here; else, empty, it receives their work (maps[0] the
                                 global map, maps[1] the caustic map or NULL, maps[2 ..]
                                 each light's visibility map with shadow photons, then
                                 the records of precomputed irradiance when N >= 1, and
                                 the cache's records), or, full, holds it to use instead
                                 (photon/global_work.h)                                  */
};

/* What the render did, for --stats. */
struct jensen1996_stats {
    size_t photons_global;            /* stored in the global map                         */
    size_t photons_caustic;           /* stored in the caustic map (0 without one)         */
    size_t photons_shadow;            /* shadow photons, in the lights' visibility maps    */
    size_t bytes_global_map, bytes_caustic_map, bytes_visibility_maps;
    size_t photons_emitted;           /* for both maps                                     */
    unsigned long long photon_rays;   /* rays cast tracing photons                         */
    double seconds_photons;           /* CPU seconds tracing and balancing the maps, and
                                         precomputing irradiance                          */
    size_t precomputed_records;       /* records of precomputed irradiance (0 without)     */
    size_t bytes_precomputed;         /* their kd-tree and values                          */
    double seconds_precompute;        /* CPU seconds estimating their irradiance           */
    unsigned long long precomputed_reads; /* approximate points (gather rays' ends among
                                             them) read from a record                    */
    unsigned long long global_estimates;  /* approximate points given the global map's own
                                             radiance estimate                           */
    double seconds_cache;             /* CPU seconds of the irradiance cache's pre-pass    */
    double seconds_final_pass;        /* CPU seconds of the final pass                     */
    unsigned long long shadow_rays;   /* shadow rays cast at accurate points               */
    unsigned long long shadow_rays_avoided; /* light tests the shadow photons decided      */
    size_t cache_records;             /* records made by the pre-pass                     */
    size_t bytes_cache;
    unsigned long long gathers;       /* final gathers (records, fallbacks, non-Lambertian) */
    unsigned long long gather_fallbacks; /* gathers of the final pass where no record was
                                           usable (computed, used once, not stored)       */
    unsigned long long gather_rays;   /* rays cast by final gathers                        */
    int strata_theta, strata_phi;     /* the gather's strata                              */
};

/* The defaults above. */
struct jensen1996_settings jensen1996_settings_default(void);

#endif
