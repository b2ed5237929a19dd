/*
 * app/render_options.h -- struct options, what the render command's options come to, and
 * the enums it holds: the mode and the preset's quality.
 *
 * A header of its own because the option parser (options.c) and the pieces it calls all
 * work on it: the value readers and defaults (option_values.h), the presets (presets.h)
 * and the combination checks (option_checks.h) take it from here, so that none of them
 * includes options.h, which includes them.
 */
#ifndef PHOTON_RENDER_OPTIONS_H
#define PHOTON_RENDER_OPTIONS_H

#include <stdint.h>

#include "../image/image.h"

#define OUTPUT_PATH_MAX 1024

enum mode {
    MODE_DIRECT,
    MODE_PT,
    MODE_PHOTONS,
    MODE_JENSEN1994,
    MODE_JENSEN1996,
    MODE_PPM2008,
    MODE_SPPM2009
};

/* --quality: which of a mode's presets (app/presets.h) stands before the user's options. */
enum quality { QUALITY_PREVIEW, QUALITY_DEFAULT, QUALITY_REFERENCE };

struct options {
    const char *scene_path;       /* the scene file (borrowed from argv)           */
    char output[OUTPUT_PATH_MAX]; /* the PFM to write, whatever -o's name ended in  */
    enum display_format display;  /* the display image beside it: -o's ending       */
    enum mode mode;
    enum quality quality;         /* the preset applied before the command line's words */
    int paper;                    /* --paper: the mode's departures off (app/presets.h),
                                     and specular pixels take --spp samples          */
    uint64_t seed;
    int spp;                      /* samples per pixel; 0 = the mode's default      */
    int specular_spp;             /* samples of a pixel that sees a light through
                                     mirrors or glass; 0 = the mode's default       */
    int max_depth;                /* longest path followed; -1 = the mode's default */
    int width, height;            /* 0 = the scene's own size                      */
    int crop[4];                  /* --crop's x0 y0 x1 y1, when has_crop           */
    int has_crop;                 /* whether --crop was given                      */
    int stats;                    /* print key=value statistics on stderr          */
    int progress;                 /* 1 on, 0 off, -1 decided from the environment  */
    double exposure;              /* multiplier applied before the display sRGB curve */
    double time_limit;            /* CPU seconds, 0 = none                          */
    const char *reference;        /* --reference REF.pfm, or NULL (borrowed)        */
    const char *report;           /* --report FILE.csv, or NULL (borrowed)          */
    const char *variance;         /* --variance FILE.pfm, or NULL (borrowed)        */
    const char *error;            /* --error FILE.pfm, or NULL (borrowed)           */
    const char *block_error;      /* --block-error FILE.pfm, or NULL (borrowed)     */
    double confidence;            /* --error's confidence, 0 < c < 1                */
    double target_error;          /* --target-error E, 0 = none                     */
    const char *save_photons;     /* --save-photons FILE, or NULL (borrowed)        */
    const char *load_photons;     /* --load-photons FILE, or NULL (borrowed)        */
    int photons;                  /* photon modes: photons emitted                 */
    int gather;                   /* photon modes: photons per radiance estimate   */
    double max_radius;            /* photon modes: largest gathering radius; 0 =
                                     none, the papers' (--no-max-radius); -1 = the
                                     default, 1/10 of the scene's diagonal          */
    double cone;                  /* photon modes: cone filter k; 0 = none, -1 = the
                                     mode's default (photons 0, 1996 1)            */
    int exclude_rim;              /* photon modes: estimates leave the rim photon out;
                                     0 counts it, as Eq. 3 is printed              */
    double caustic_radius_fraction; /* 1994, 1996: caustic estimates' reach, a fraction
                                     of max_radius                                  */
    int caustic_photons;          /* 1996: photons emitted for the caustic map     */
    int caustic_gather;           /* 1996: photons in each caustic estimate        */
    int gather_rays;              /* 1996: rays of one final gather                */
    int glossy_rays;              /* 1996: rays sampling a glossy part             */
    double cache_accuracy;        /* 1996: Ward's a; 0 = no irradiance cache       */
    double accurate_distance;     /* 1996: corner threshold, in estimate radii     */
    double accurate_weight;       /* 1996: throughput below which rays go rough    */
    int shadow_rays;              /* 1996: cast every shadow ray; 0 = shadow photons
                                     decide where they agree, the paper's          */
    int one_map;                  /* 1996: one map for global and caustic photons  */
    int precomputed_irradiance;   /* 1994, 1996: records at every N-th photon; 0 = none,
                                     the paper's (--no-precomputed-irradiance)      */
    int disc_coverage;            /* 1996: records over their disc's covered part  */
    int both_lobes;               /* 1994, 1996: mirrors and glass trace every lobe */
    int glossy_corner;            /* 1996: the corner way behind glossy lobes      */
    int corner_photons;           /* 1996: corners' soft indirect light from photons;
                                     0 = a final gather, the paper's               */
    int bounded_reach;            /* 1994, 1996: cache records' R from the camera  */
    int glossy_photons;           /* 1994: seen through glossy lobes: photon map    */
    int lobe_lights;              /* 1994: lights sampled through glossy lobes      */
    int gradient_limit;           /* 1994, 1996: cache records' R <= E / |grad E|  */
    double adaptive;              /* camera modes: adaptive sampling's relative error;
                                     0 = off                                       */
    int differential_run;         /* 1994: differential checking's run; 0 = off    */
    int light_samples;            /* 1994: stratified samples of each light        */
    int projection_maps;          /* 1994: emit through projection maps            */
    int illumination_maps;        /* 1994: --irradiance-store illumination         */
    int passes;                   /* 2008, 2009: photon passes                     */
    int photons_per_pass;         /* 2008, 2009: photons traced in each pass       */
    double alpha;                 /* 2008, 2009: Eq. 7's alpha, in (0, 1)          */
    double radius;                /* 2008, 2009: initial radius; 0 = pixel footprints */
    double footprints;            /* 2008, 2009: initial radius in pixel footprints */
    int fit_radius;               /* 2008, 2009: initial radius fitted to the surface */
    double caustic_footprints;    /* 2008: caustic estimate's R0; 0 = none, the
                                     paper's (--no-caustic-footprints)              */
    int merge_hit_points;         /* 2008: a pixel's eye rays share hit points     */
    int resample_emission;        /* 2008: each pass's eye ray adds emission       */
    int facing_test;              /* 2008: photons count where surfaces face       */
    int turn_photon_directions;   /* 2008, 2009: w_p turned onto the hit point's surface */
    int follow_glossy_lobes;      /* 2009: eye paths sample glossy lobes                  */
    int checkpoint;               /* 2008, 2009: write the image every this many passes */
    int direct_light_samples;     /* 2008, 2009: direct light by light samples; 0 =
                                     from photons, the paper's                      */
};

#endif
