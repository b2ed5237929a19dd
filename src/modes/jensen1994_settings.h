/*
 * modes/jensen1994_settings.h -- the settings of `--mode 1994`, their defaults
 * (jensen1994_settings.c), and the figures the render reports for --stats.
 *
 * A header of its own because both passes read them: pass 1 (jensen1994_maps.h) and the
 * render that calls it (jensen1994.h) take them from here, so neither includes the other.
 */
#ifndef PHOTON_JENSEN1994_SETTINGS_H
#define PHOTON_JENSEN1994_SETTINGS_H

#include <stddef.h>

#include "../photon/global_work.h"

#define J94_DEFAULT_PHOTONS 4000000    /* --photons: light rays of pass 1; searches cost
                                          log N, so a large map is cheap, and its
                                          estimates' discs, hanging over the walls'
                                          edges, are small (src/modes/README.md)         */
#define J94_DEFAULT_SPP 64             /* --spp: the cache and maps are shared by all
                                          samples, so the final pass is the cheap part;
                                          fewer leave the light's outline aliased
                                          (src/modes/measured.md)                        */
#define J94_DEFAULT_GATHER 50          /* --gather: photons in an irradiance estimate
                                          (the paper used 40 on the desk, 80 on the
                                          landscape, 200 for its Fig. 8); more widen the
                                          discs, which darken the open front's corners
                                          (src/modes/measured.md)                        */
#define J94_DEFAULT_GATHER_RAYS 512    /* --gather-rays: irradiance-gradient rays of one
                                          cache record (Ward and Heckbert's strata);
                                          with fewer, a record's noise near the glass
                                          ball puts whole blocks past 3%
                                          (src/modes/measured.md)                        */
#define J94_DEFAULT_LIGHT_SAMPLES 4    /* --light-samples: stratified samples of each light
                                          at a surface (2 x 2)                           */
#define J94_DEFAULT_CACHE_ACCURACY 0.15 /* --cache-accuracy: Ward's a                     */
#define J94_MAX_LIGHT_SAMPLES 1024     /* documented limit on --light-samples            */
#define J94_DEFAULT_PRECOMPUTED 16     /* --precomputed-irradiance: records at every N-th
                                          photon of the map (src/modes/measured.md)      */

struct jensen1994_settings {
    size_t n_photons;      /* light rays emitted in pass 1, 1..MAX_PHOTONS (trace.h)        */
    size_t gather;         /* n, photons in each irradiance estimate, 1..MAX_GATHER         */
    double max_radius;     /* > 0: the estimates' largest radius; 0: none, the paper's;
                              < 0: 1/10 of the scene's diagonal (as the photons mode)       */
    int differential_run;  /* differential checking's run (estimate.h); 0: off              */
    int exclude_rim;       /* 1: each estimate leaves out its rim photon (a departure);
                              0: counts it, the paper's sum                                 */
    int gather_rays;       /* rays of one irradiance record, 2..J96_MAX_GATHER_RAYS         */
    double cache_accuracy; /* Ward's a, > 0                                                 */
    int light_samples;     /* stratified samples of each light, 1..J94_MAX_LIGHT_SAMPLES    */
    double caustic_radius_fraction; /* caustic estimates reach this fraction of the
                              largest radius, in (0, 1] (CAUSTIC_RADIUS_FRACTION)           */
    int both_lobes;        /* 1: L_r,s follows both lobes of glass (Whitted's way, a
                              departure); 0: one lobe sampled by the BRDF, the paper's
                              "recursive Monte Carlo ray tracing"                       */
    int glossy_photons;    /* 1: surfaces seen through a glossy lobe read the photon map
                              (a departure); 0: evaluated in full, the paper's            */
    int lobe_lights;       /* 1: area lights and the sky are sampled through a glossy lobe
                              of f_r,s too, weighted against the lobe's traced ray by the
                              power heuristic (a departure); 0: the traced ray alone finds
                              them, the paper's                                         */
    int bounded_reach;     /* 1: cache records' R bounded from the camera's view
                           (record_radius_bounds(), a departure); 0: Ward's R alone     */
    int gradient_limit;    /* 1: a record's R at most E / |grad E| (a departure); 0: not */
    int precomputed_irradiance; /* N >= 1: a gather ray's end reads irradiance precomputed
                                   at every N-th photon of the map (Christensen 1999, a
                                   departure); 0: its own estimate, the paper's          */
    int projection_maps;   /* 1: emit through projection maps (Sec. 3.1, photon/
                              projection_map.h, default cells and boost); 0: light_emit() */
    int illumination_maps; /* --irradiance-store: 1 illumination maps on quads and spheres
                              and photon maps elsewhere (the paper's Fig. 4); 0 photon
                              maps everywhere (Fig. 5)                                     */
    struct global_work *work; /* NULL: pass 1 and the cache's pre-pass run and are released
                                 here; else, empty, it receives their work (maps[0] the
                                 photon map, maps[1] the CP photons' tree, maps[2] the
                                 glossy photons', the illumination maps, the cache's
                                 records), or, full, holds it to use instead
                                 (photon/global_work.h)                                  */
};

/* What the render did, for --stats (the paper's Fig. 9 and more). */
struct jensen1994_stats {
    size_t photons_emitted;          /* light rays of pass 1                             */
    unsigned long long photon_rays;  /* rays cast tracing them                           */
    size_t photons_stored;           /* in the photon map: CP + DP                       */
    size_t photons_caustic;          /* CP, but for the glossy tree's                    */
    size_t photons_glossy;           /* those that keep their direction (their own tree) */
    size_t bytes_photon_map;
    size_t bytes_caustic_photons;    /* the copies of the CP photons in their own tree    */
    size_t projection_maps;          /* emission positions over all lights (0: maps off)  */
    double projection_marked;        /* share of the lights' power the maps emit          */
    size_t bytes_projection_maps;
    size_t illumination_maps;        /* surfaces with a DI map (0: photon maps only)      */
    size_t illumination_di_elements;
    size_t illumination_ci_maps;     /* CI sub-maps created where caustics landed         */
    size_t bytes_illumination_maps;
    double seconds_photons;          /* pass 1, tracing and balancing                     */
    double seconds_precompute;       /* the records of precomputed irradiance            */
    double seconds_cache;            /* the irradiance cache's pre-pass                   */
    double seconds_final_pass;       /* the final pass                                    */
    size_t precomputed_records;      /* records of precomputed irradiance (0 without)     */
    size_t bytes_precomputed;        /* their kd-tree and values                          */
    size_t cache_records;
    size_t bytes_cache;
    unsigned long long gradient_rays; /* rays of the irradiance records (IG rays)          */
    unsigned long long gather_fallbacks; /* records made in the final pass and not kept    */
    unsigned long long shadow_rays;
    int strata_theta, strata_phi;    /* the records' strata                               */
};

struct jensen1994_settings jensen1994_settings_default(void);

#endif
