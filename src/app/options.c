/*
 * app/options.c -- parsing the render command's options (options.h); option_checks.c
 * refuses those that do not go together.
 */
#include "options.h"

#include <assert.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "../base/hash.h"
#include "../modes/jensen1994.h"
#include "../modes/jensen1996.h"
#include "../modes/photons.h"
#include "../modes/ppm2008.h"
#include "../photon/trace.h"
#include "help.h"
#include "option_checks.h"
#include "option_values.h"
#include "presets.h"
#include "suggest.h"

/* A departure from a mode's paper is switched by a pair of options: --NAME, its default
 * side, and --no-NAME, the paper's (--paper's words are such --no-NAMEs, or an option
 * with the paper's value). OPT_FLAG sets its int field to 0 when its name starts with
 * --no-, else to 1. A departure with a value is --NAME VALUE, whose range leaves out 0,
 * and --no-NAME, an OPT_OFF: it sets the field of --NAME to 0, which the modes read as
 * the departure off. */
enum option_kind {
    OPT_FLAG, OPT_OFF, OPT_INT, OPT_SEED, OPT_REAL, OPT_REAL_ABOVE, OPT_REAL_BETWEEN, OPT_MODE,
    OPT_QUALITY, OPT_OUTPUT, OPT_FILE, OPT_CROP, OPT_STORE
};

struct option_spec {
    const char *name;
    enum option_kind kind;
    size_t offset;    /* of the field in struct options */
    double min, max;  /* limits for numbers: [min, max]; OPT_REAL_ABOVE (min, max],
                         OPT_REAL_BETWEEN (min, max); --help prints them        */
    const char *args; /* what follows the name in --help */
    const char *help;
    unsigned modes;   /* the modes it means something for: bit 1 << m for enum mode m;
                         given for another, it is refused (check_modes), and --help
                         prints the modes before its text                            */
};

#define FIELD(f) offsetof(struct options, f)

/* Sets of modes for option_spec.modes. */
#define FOR_DIRECT (1u << MODE_DIRECT)
#define FOR_PT (1u << MODE_PT)
#define FOR_PHOTONS (1u << MODE_PHOTONS)
#define FOR_1994 (1u << MODE_JENSEN1994)
#define FOR_1996 (1u << MODE_JENSEN1996)
#define FOR_2008 (1u << MODE_PPM2008)
#define FOR_2009 (1u << MODE_SPPM2009)
#define FOR_ALL (FOR_DIRECT | FOR_PT | FOR_PHOTONS | FOR_1994 | FOR_1996 | FOR_2008 | FOR_2009)
#define FOR_PHOTON_MAPS (FOR_PHOTONS | FOR_1994 | FOR_1996) /* the modes that keep maps */
#define FOR_PROGRESSIVE (FOR_2008 | FOR_2009)
#define FOR_SAMPLES (FOR_ALL & ~FOR_PROGRESSIVE) /* pixels: means of independent samples */

static const struct option_spec specs[] = {
    {"--mode", OPT_MODE, FIELD(mode), 0, 0, "NAME",
     "rendering mode: direct, pt, photons, 1994, 1996, 2008 or 2009 (default direct)", FOR_ALL},
    {"--quality", OPT_QUALITY, FIELD(quality), 0, 0, "NAME",
     "preview, default or reference: the mode's preset of options (listed below), applied "
     "before the other options given (default default)", FOR_ALL},
    {"--paper", OPT_FLAG, FIELD(paper), 0, 0, "",
     "the paper as written: every departure of the mode off, before the other options "
     "given (listed below: a departure's switch is --NAME, the default, and --no-NAME, the "
     "paper's; or the paper's value of a number)", FOR_ALL},
    {"-o", OPT_OUTPUT, FIELD(output), 0, 0, "FILE.pfm|.png|.ppm",
     "output: FILE.pfm (linear radiance) and FILE.png beside it for display; -o FILE.ppm "
     "writes FILE.ppm in place of the PNG (default: SCENE's name)", FOR_ALL},
    {"--seed", OPT_SEED, FIELD(seed), 0, 0, "N", "random seed, 0..2^64-1 (default 1)", FOR_ALL},
    {"--spp", OPT_INT, FIELD(spp), 1, MAX_SPP, "N",
     "camera samples per pixel (default 16; 1994: 64; 1996: 128; 2008: eye rays per pixel, "
     "default 16)", FOR_ALL & ~FOR_2009},
    {"--specular-spp", OPT_INT, FIELD(specular_spp), 1, MAX_SPP, "N",
     "camera samples of a pixel in which the camera sees a light through mirrors or glass, "
     "at least --spp (default: --spp; 1994, 1996: 64 x --spp)", FOR_SAMPLES},
    {"--width", OPT_INT, FIELD(width), 1, MAX_IMAGE_SIDE, "N", "image width (default: scene's)",
     FOR_ALL},
    {"--height", OPT_INT, FIELD(height), 1, MAX_IMAGE_SIDE, "N",
     "image height (default: scene's)", FOR_ALL},
    {"--crop", OPT_CROP, FIELD(crop), 0, MAX_IMAGE_SIDE, "X0 Y0 X1 Y1",
     "render only pixels X0 <= x < X1, Y0 <= y < Y1 of the whole image (0,0 = top left); "
     "also writes FILE.pfm.window for photon merge", FOR_ALL},
    {"--adaptive", OPT_REAL, FIELD(adaptive), 0, 1e6, "E",
     "stop sampling a pixel (after 4 samples, at powers of two) once its mean's standard "
     "error is at most E times the mean (Jensen & Christensen 1994); 0 = off (default 0); "
     "refused where no pixel takes more than 4 samples", FOR_SAMPLES},
    {"--max-depth", OPT_INT, FIELD(max_depth), 0, MAX_DEPTH_LIMIT, "N",
     "longest chain of bounces followed (default: direct 16, others 1000)", FOR_ALL},
    {"--time-limit", OPT_REAL_ABOVE, FIELD(time_limit), 0, 1e9, "SECONDS",
     "start no sample pass (photon pass in 2008, 2009) once this process has used this many "
     "CPU seconds (C's clock()): the pass running then finishes, so the render takes a "
     "pass longer; the mode's set-up (photon maps, the cache) is not cut (default: none)",
     FOR_ALL},
    {"--reference", OPT_FILE, FIELD(reference), 0, 0, "REF.pfm",
     "with --report: the converged image to measure error against (whole-image size)", FOR_ALL},
    {"--report", OPT_FILE, FIELD(report), 0, 0, "FILE.csv",
     "write seconds,work,rmse,relmse at work 1, 2, 4, ... and at the end", FOR_ALL},
    {"--variance", OPT_FILE, FIELD(variance), 0, 0, "FILE.pfm",
     "also write each pixel's variance of the mean (needs --spp >= 2)", FOR_SAMPLES},
    {"--error", OPT_FILE, FIELD(error), 0, 0, "FILE.pfm",
     "also write each pixel's bound on |pixel - truth| at --confidence, from its samples' "
     "and its 5 x 5 neighbours' spread (needs --spp >= 16); 2008, 2009: from its passes' "
     "spread and, added, its photon estimates' bias, from discs of half the area (needs "
     "--passes >= 16)", FOR_PT | FOR_PROGRESSIVE},
    {"--block-error", OPT_FILE, FIELD(block_error), 0, 0, "FILE.pfm",
     "with --error: also write each 16 x 16 block's bound on |block mean - truth|, one pixel "
     "a block, for photon compare --test-block-error (not with --crop)", FOR_PT | FOR_PROGRESSIVE},
    {"--confidence", OPT_REAL_BETWEEN, FIELD(confidence), 0, 1, "C",
     "the confidence of --error's bound: the truth is within it in a fraction C of the "
     "pixels (default 0.95)", FOR_PT | FOR_PROGRESSIVE},
    {"--target-error", OPT_REAL_ABOVE, FIELD(target_error), 0, 1, "E",
     "sample until every 16 x 16 block's bound at --confidence is at most E times its mean "
     "(blocks darker than 1e-3 aside), --spp at most (default with it: 1048576), or the "
     "time limit; 2008, 2009: passes until then, --passes at most (default with it: "
     "1048576)", FOR_PT | FOR_PROGRESSIVE},
    {"--save-photons", OPT_FILE, FIELD(save_photons), 0, 0, "FILE",
     "also write the global work (photon maps, 1994's illumination "
     "maps, irradiance cache) to FILE, for --load-photons", FOR_PHOTON_MAPS},
    {"--load-photons", OPT_FILE, FIELD(load_photons), 0, 0, "FILE",
     "read the global work from FILE (saved by the same command but "
     "for -o, --crop and the like) instead of doing it", FOR_PHOTON_MAPS},
    {"--photons", OPT_INT, FIELD(photons), 1, MAX_PHOTONS, "N",
     "photons emitted (default: photons 200000, 1994 4000000, 1996 1250000 for "
     "the global map)", FOR_PHOTON_MAPS},
    {"--gather", OPT_INT, FIELD(gather), 1, MAX_GATHER, "K",
     "photons in each radiance or irradiance estimate (default 100; 1994: 50; 1996: 40)",
     FOR_PHOTON_MAPS},
    {"--max-radius", OPT_REAL_ABOVE, FIELD(max_radius), 0, 1e30, "R",
     "largest gathering radius (default: 1/10 of the scene's diagonal)",
     FOR_PHOTON_MAPS},
    {"--cone", OPT_REAL, FIELD(cone), 0, 1e6, "K",
     "cone filter constant k >= 1 (Jensen 1996 Eq. 4); 0 = none (default: "
     "photons 0, 1996 1 on caustics)", FOR_PHOTONS | FOR_1996},
    {"--exclude-rim-photon", OPT_FLAG, FIELD(exclude_rim), 0, 0, "",
     "estimates leave out the k-th photon, which only marks the radius r (the default)",
     FOR_PHOTON_MAPS},
    {"--no-exclude-rim-photon", OPT_FLAG, FIELD(exclude_rim), 0, 0, "",
     "count it too, as Eq. 3 is printed (the paper's; k / (k - 1) too bright)",
     FOR_PHOTON_MAPS},
    {"--caustic-radius-fraction", OPT_REAL, FIELD(caustic_radius_fraction), 0.001, 1, "F",
     "caustic estimates reach F times --max-radius (default 0.25: a wide disc hangs over a "
     "surface's edges where caustic photons are sparse; the paper's 1)", FOR_1994 | FOR_1996},
    {"--caustic-photons", OPT_INT, FIELD(caustic_photons), 0, MAX_PHOTONS, "N",
     "photons emitted towards specular objects for the caustic map (default 1000000); with "
     "0 and no --one-map, --caustic-gather, --caustic-radius-fraction and --cone are "
     "refused", FOR_1996},
    {"--caustic-gather", OPT_INT, FIELD(caustic_gather), 1, MAX_GATHER, "K",
     "photons in each caustic estimate (default 60)", FOR_1996},
    {"--gather-rays", OPT_INT, FIELD(gather_rays), 2, J96_MAX_GATHER_RAYS, "N",
     "rays of one final gather (1994: one per stratum; 1996: half stratified, "
     "half by photon importance; default 512)", FOR_1994 | FOR_1996},
    {"--glossy-rays", OPT_INT, FIELD(glossy_rays), 1, 1000, "N",
     "rays sampling a glossy surface seen accurately (default 6, the paper's)", FOR_1996},
    {"--cache-accuracy", OPT_REAL, FIELD(cache_accuracy), 0, 10, "A",
     "irradiance cache accuracy a (Ward 1988); 1996 only: 0 = gather at every "
     "point, and the switches of a record's R (--bounded-reach, --gradient-limit) are "
     "refused (default 0.15)", FOR_1994 | FOR_1996},
    {"--accurate-distance", OPT_REAL, FIELD(accurate_distance), 0, 1e6, "F",
     "gather rays shorter than F radii of the estimate they reach are evaluated "
     "accurately (default 3)", FOR_1996},
    {"--accurate-weight", OPT_REAL, FIELD(accurate_weight), 0, 1, "W",
     "rays with throughput below W are evaluated approximately (default 0.1)", FOR_1996},
    {"--shadow-rays", OPT_FLAG, FIELD(shadow_rays), 0, 0, "",
     "cast every shadow ray, and store no shadow photons (the default)", FOR_1996},
    {"--no-shadow-rays", OPT_FLAG, FIELD(shadow_rays), 0, 0, "",
     "decide a light's visibility from shadow photons where they agree, a ray where they "
     "do not (the paper's)", FOR_1996},
    {"--one-map", OPT_FLAG, FIELD(one_map), 0, 0, "",
     "one global map of as many photons in place of the caustic and the global map that "
     "the paper and the default keep", FOR_1996},
    {"--precomputed-irradiance", OPT_INT, FIELD(precomputed_irradiance), 1,
     J96_MAX_PRECOMPUTED, "N",
     "gather rays read irradiance precomputed at every N-th global photon (Christensen "
     "1999; default 16)", FOR_1996},
    {"--no-precomputed-irradiance", OPT_OFF, FIELD(precomputed_irradiance), 0, 0, "",
     "a radiance estimate at each gather ray's end (the paper's)", FOR_1996},
    {"--disc-coverage", OPT_FLAG, FIELD(disc_coverage), 0, 0, "",
     "records of precomputed irradiance (2009: a pixel's estimate) count the photons of "
     "their disc's plane over the part of the disc a surface covers, found by probe rays "
     "(2009: one a pass), in place of pi r^2 (the default); 1996: refused with "
     "--no-precomputed-irradiance, which makes no records", FOR_1996 | FOR_2009},
    {"--no-disc-coverage", OPT_FLAG, FIELD(disc_coverage), 0, 0, "",
     "over the whole disc, pi r^2, as Eq. 3 (the paper's)", FOR_1996 | FOR_2009},
    {"--both-lobes", OPT_FLAG, FIELD(both_lobes), 0, 0, "",
     "glass traces its reflected and refracted rays both, as Whitted's ray tracer (1996: "
     "at accurate points) (the default)", FOR_1994 | FOR_1996},
    {"--no-both-lobes", OPT_FLAG, FIELD(both_lobes), 0, 0, "",
     "one of them, chosen by the BRDF's importance sampling (the paper's Monte Carlo)",
     FOR_1994 | FOR_1996},
    {"--glossy-corner", OPT_FLAG, FIELD(glossy_corner), 0, 0, "",
     "surfaces seen through a glossy lobe take the global map's caustic and indirect light, "
     "no gather (the default)", FOR_1996},
    {"--no-glossy-corner", OPT_FLAG, FIELD(glossy_corner), 0, 0, "",
     "evaluate them accurately, with a final gather (the paper's)", FOR_1996},
    {"--glossy-photons", OPT_FLAG, FIELD(glossy_photons), 0, 0, "",
     "surfaces seen through a glossy lobe read the photon map, as a gather ray's end, with no "
     "final gather (the default)", FOR_1994},
    {"--no-glossy-photons", OPT_FLAG, FIELD(glossy_photons), 0, 0, "",
     "evaluate them in full, with a final gather (the paper's)", FOR_1994},
    {"--lobe-lights", OPT_FLAG, FIELD(lobe_lights), 0, 0, "",
     "area lights and the sky are sampled through a glossy lobe of a surface the eye sees, "
     "weighted against the lobe's own ray by the power heuristic (the default)", FOR_1994},
    {"--no-lobe-lights", OPT_FLAG, FIELD(lobe_lights), 0, 0, "",
     "the lobe's ray alone finds them (the paper's; point lights are sampled either way)",
     FOR_1994},
    {"--glossy-gather", OPT_FLAG, FIELD(glossy_gather), 0, 0, "",
     "a diffuse-like part that is not Lambertian (Schlick's model, r >= 1/2) reflects what "
     "each camera sample gathers through its BRDF (the default)", FOR_1994},
    {"--no-glossy-gather", OPT_FLAG, FIELD(glossy_gather), 0, 0, "",
     "albedo / pi times the cache's irradiance, as a Lambertian surface (the paper's)",
     FOR_1994},
    {"--bounded-reach", OPT_FLAG, FIELD(bounded_reach), 0, 0, "",
     "a cache record's R lies between 1.5 pixel footprints / A, as the camera sees its "
     "point, and a fifth of the scene's diagonal (the default)", FOR_1994 | FOR_1996},
    {"--no-bounded-reach", OPT_FLAG, FIELD(bounded_reach), 0, 0, "",
     "R is Ward's harmonic mean distance alone (the paper's; many more gathers in "
     "corners)", FOR_1994 | FOR_1996},
    {"--gradient-limit", OPT_FLAG, FIELD(gradient_limit), 0, 0, "",
     "a cache record's R is at most E / |grad E|, so it stops short of a shadow's edge "
     "(the default)", FOR_1994 | FOR_1996},
    {"--no-gradient-limit", OPT_FLAG, FIELD(gradient_limit), 0, 0, "",
     "R is not limited by the gradient (Ward and Heckbert's, the paper's)",
     FOR_1994 | FOR_1996},
    {"--differential", OPT_INT, FIELD(differential_run), 0, 100000, "R",
     "stop an irradiance estimate after R additions that all raise or all lower it "
     "(differential checking); 0 = off (default 10)", FOR_1994},
    {"--light-samples", OPT_INT, FIELD(light_samples), 1, J94_MAX_LIGHT_SAMPLES, "N",
     "stratified samples of each light, rounded down to a square (default 4)", FOR_1994},
    {"--irradiance-store", OPT_STORE, FIELD(illumination_maps), 0, 0, "photon|illumination",
     "photon maps everywhere (the paper's Fig. 5), or illumination maps on quads and "
     "spheres and photon maps elsewhere (Fig. 4) (default photon)", FOR_1994},
    {"--no-projection-maps", OPT_FLAG, FIELD(projection_maps), 0, 0, "",
     "emit photons into all directions, not through projection maps as the paper (Sec. "
     "3.1) and the default do", FOR_1994},
    {"--passes", OPT_INT, FIELD(passes), 1, MAX_PASSES, "N",
     "photon passes (default 144; 2009: 256, each with one new eye path a pixel; 1048576 "
     "with --target-error; --time-limit may stop sooner)", FOR_PROGRESSIVE},
    {"--photons-per-pass", OPT_INT, FIELD(photons_per_pass), 1, MAX_PHOTONS, "N",
     "photons traced in each pass (default 100000)", FOR_PROGRESSIVE},
    {"--alpha", OPT_REAL_BETWEEN, FIELD(alpha), 0, 1, "A",
     "fraction of new photons kept (Eq. 7; default 0.7)", FOR_PROGRESSIVE},
    {"--radius", OPT_REAL_ABOVE, FIELD(radius), 0, 1e30, "R",
     "initial radius in scene units (default: --footprints pixel footprints at each hit "
     "point); --footprints and --fit-radius, which it leaves unused, are refused with it",
     FOR_PROGRESSIVE},
    {"--footprints", OPT_REAL_ABOVE, FIELD(footprints), 0, 1e6, "K",
     "initial radius in pixel footprints at each hit point (default 4; the paper's: 1); "
     "refused with --radius", FOR_PROGRESSIVE},
    {"--caustic-footprints", OPT_REAL_ABOVE, FIELD(caustic_footprints), 0, 1e6, "K",
     "caustic photons gather in an estimate of their own, R0 of K footprints (with "
     "--radius: R0 = --radius, whatever K; default 1)", FOR_2008},
    {"--no-caustic-footprints", OPT_OFF, FIELD(caustic_footprints), 0, 0, "",
     "caustic photons in the one estimate (the paper's)", FOR_2008},
    {"--fit-radius", OPT_FLAG, FIELD(fit_radius), 0, 0, "",
     "shorten each initial radius until its disc lies on its surface, clear of walls and "
     "open edges (2009 with --disc-coverage: clear of walls the surface goes on past) "
     "(the default); refused with --radius, as is --no-fit-radius", FOR_PROGRESSIVE},
    {"--no-fit-radius", OPT_FLAG, FIELD(fit_radius), 0, 0, "",
     "keep the initial radius whole, the paper's", FOR_PROGRESSIVE},
    {"--merge-hit-points", OPT_FLAG, FIELD(merge_hit_points), 0, 0, "",
     "a pixel's eye rays that meet a surface within a hit point's disc add to it (the "
     "default)", FOR_2008},
    {"--no-merge-hit-points", OPT_FLAG, FIELD(merge_hit_points), 0, 0, "",
     "a hit point for every eye ray, the paper's", FOR_2008},
    {"--resample-emission", OPT_FLAG, FIELD(resample_emission), 0, 0, "",
     "each pass's new eye ray also adds the emission it sees (the default)", FOR_2008},
    {"--no-resample-emission", OPT_FLAG, FIELD(resample_emission), 0, 0, "",
     "emission only from the --spp eye rays of the ray tracing pass, the paper's", FOR_2008},
    {"--facing-test", OPT_FLAG, FIELD(facing_test), 0, 0, "",
     "a photon counts only at hit points whose surface faces its own (the default)",
     FOR_PROGRESSIVE},
    {"--no-facing-test", OPT_FLAG, FIELD(facing_test), 0, 0, "",
     "every photon within R counts (the papers leave the test open)", FOR_PROGRESSIVE},
    {"--direct-light-samples", OPT_FLAG, FIELD(direct_light_samples), 0, 0, "",
     "direct light by a light sample at each hit point each pass, photons only after their "
     "first bounce (the default)", FOR_PROGRESSIVE},
    {"--no-direct-light-samples", OPT_FLAG, FIELD(direct_light_samples), 0, 0, "",
     "direct light from photons too (the paper's)", FOR_PROGRESSIVE},
    {"--checkpoint", OPT_INT, FIELD(checkpoint), 1, MAX_PASSES, "K",
     "write the image (-o) every K passes, each write complete (default: at the end); "
     "refused for K >= --passes", FOR_PROGRESSIVE},
    {"--exposure", OPT_REAL, FIELD(exposure), 0, 1e30, "E",
     "PNG or PPM only (not the PFM): multiply radiance by E before sRGB encoding "
     "(default 1)", FOR_ALL},
    {"--stats", OPT_FLAG, FIELD(stats), 0, 0, "", "print key=value statistics on stderr", FOR_ALL},
    {"--progress", OPT_FLAG, FIELD(progress), 0, 0, "", "show a progress line on stderr", FOR_ALL},
    {"--no-progress", OPT_FLAG, FIELD(progress), 0, 0, "", "never show the progress line", FOR_ALL},
};
#define N_SPECS (sizeof specs / sizeof specs[0])

static const enum mode every_mode[] = {MODE_DIRECT, MODE_PT, MODE_PHOTONS, MODE_JENSEN1994,
                                       MODE_JENSEN1996, MODE_PPM2008, MODE_SPPM2009};
#define N_MODES (sizeof every_mode / sizeof every_mode[0])

/* The modes of set (an option_spec.modes) into text[size], in the order of every_mode,
 * separated by ", ", the last by last (", " or " or "): "photons, 1994 or 1996". */
static void mode_list(unsigned set, const char *last, char *text, size_t size)
{
    size_t n = 0, listed = 0, count = 0;
    for (size_t m = 0; m < N_MODES; m++)
        count += (set >> every_mode[m]) & 1u;
    text[0] = '\0';
    for (size_t m = 0; m < N_MODES && n < size; m++) {
        if (!((set >> every_mode[m]) & 1u))
            continue;
        const char *separator = listed == 0 ? "" : listed + 1 == count ? last : ", ";
        n += (size_t)snprintf(text + n, size - n, "%s%s", separator, mode_name(every_mode[m]));
        listed++;
    }
}

/* What --help says of the modes an option is for, before its text: nothing when it is for
 * every mode, "not with MODES: " when it is for all but one or two, else "MODES: ". */
static void mode_note(unsigned set, char *text, size_t size)
{
    char modes[64];
    unsigned missing = FOR_ALL & ~set;
    if (missing == 0) {
        text[0] = '\0';
        return;
    }
    unsigned but_one = missing & (missing - 1);
    int most = (but_one & (but_one - 1)) == 0; /* one or two modes missing */
    mode_list(most ? missing : set, most ? " or " : ", ", modes, sizeof modes);
    snprintf(text, size, "%s%s: ", most ? "not with " : "", modes);
}

/* The number read_number() reads for a numeric option. */
static enum number_kind number_kind_of(const struct option_spec *spec)
{
    return spec->kind == OPT_INT || spec->kind == OPT_CROP ? NUMBER_WHOLE
           : spec->kind == OPT_REAL_ABOVE                  ? NUMBER_ABOVE
           : spec->kind == OPT_REAL_BETWEEN                ? NUMBER_BETWEEN
                                                           : NUMBER_REAL;
}

/* What --help says of spec's value after its text: its range, for a number. */
static void value_note(const struct option_spec *spec, char *text, size_t size)
{
    char range[96];
    int numeric = spec->kind == OPT_INT || spec->kind == OPT_REAL ||
                  spec->kind == OPT_REAL_ABOVE || spec->kind == OPT_REAL_BETWEEN ||
                  spec->kind == OPT_CROP;
    text[0] = '\0';
    if (!numeric)
        return;
    number_range(number_kind_of(spec), spec->min, spec->max, range, sizeof range);
    snprintf(text, size, " (%s: %s)", spec->kind == OPT_CROP ? "each" : spec->args, range);
}

static void print_help(enum help_format format)
{
    help_begin(format, PHOTON_VERSION);
    if (format == HELP_ROFF)
        help_section(format, "synopsis");
    help_lines(format, "usage: photon [options] SCENE       render SCENE: a scene file, or an NFF file by its\n"
           "                                    .nff name (see README: Scene files)\n"
           "       photon compare A.pfm B.pfm [--diff OUT.png|.ppm] [--block N] [--alpha ALPHA]\n"
           "                      [--ref-variance VB.pfm | --ref-error EB.pfm] [--confidence C]\n"
           "                      [--test-variance VA.pfm | --test-error EA.pfm] [--exit-status]\n"
           "                      (photon compare --help: the test and every field it prints)\n"
           "       photon plot A.csv [B.csv ...] -o PLOT.svg      (relmse against seconds)\n"
           "       photon plot --linear --x COL --y COL [--y COL]... [--x-title T]\n"
           "                   [--y-title T] A.csv [B.csv ...] -o PLOT.svg\n"
           "       photon probe SCENE --line X0 Y0 Z0 X1 Y1 Z1 --samples N -o FILE.csv\n"
           "                   [--normal NX NY NZ] [--photons N] [--gather N]\n"
           "                   [--differential R] [--seed S]   (irradiance along a line)\n"
           "       photon merge -o FULL.pfm TILE.pfm [TILE.pfm ...] [--exposure E]\n"
           "       photon export --format pbrt|mitsuba|blender SCENE -o OUT [--spp N]\n"
           "                    [--channel R|G|B]   (the scene for pbrt-v4, Mitsuba 3 or\n"
           "                    Blender; see README: Rendering our scenes elsewhere)\n");
    help_section(format, "options");
    for (size_t i = 0; i < N_SPECS; i++) {
        char left[40], note[80], range[128], text[1024];
        snprintf(left, sizeof left, "%s %s", specs[i].name, specs[i].args);
        mode_note(specs[i].modes, note, sizeof note);
        value_note(&specs[i], range, sizeof range);
        snprintf(text, sizeof text, "%s%s%s", note, specs[i].help, range);
        help_option(format, left, text);
    }
    help_option(format, "--help", "print this and exit");
    help_option(format, "--version", "print the version and exit");
    help_option(format, "--manual", "print this as a manual page (roff; make install writes "
                                    "photon.1 from it) and exit");
    print_presets(format);
}

static const char *mode_at(size_t i) { return mode_name(every_mode[i]); } /* suggest.h */
static const char *spec_at(size_t i) { return specs[i].name; }

static int read_mode(const char *text, enum mode *mode, struct error *err)
{
    char hint[80];
    for (size_t i = 0; text != NULL && i < N_MODES; i++)
        if (strcmp(text, mode_name(every_mode[i])) == 0) {
            *mode = every_mode[i];
            return 0;
        }
    did_you_mean(text, mode_at, N_MODES, hint, sizeof hint);
    return error_set(err, "", 0, "--mode: unknown mode '%s'%s (available: direct, pt, photons, "
                     "1994, 1996, 2008, 2009)", text != NULL ? text : "nothing", hint);
}

static const struct option_spec *find_spec(const char *name)
{
    for (size_t i = 0; i < N_SPECS; i++)
        if (strcmp(specs[i].name, name) == 0)
            return &specs[i];
    return NULL;
}

/* Applies option spec to the value words at argv[*i + 1 ...], advancing *i past them. */
static int apply_option(const struct option_spec *spec, char **argv, int argc, int *i,
                        struct options *o, struct error *err)
{
    char *field = (char *)o + spec->offset;
    const char *value = *i + 1 < argc ? argv[*i + 1] : NULL;
    double v;
    switch (spec->kind) {
    case OPT_FLAG:
        *(int *)field = strncmp(spec->name, "--no-", 5) != 0;
        return 0;
    case OPT_OFF: {
        char name[64];
        snprintf(name, sizeof name, "--%s", spec->name + strlen("--no-"));
        const struct option_spec *on = find_spec(name);
        assert(on != NULL && on->offset == spec->offset);
        if (on->kind == OPT_INT)
            *(int *)field = 0;
        else
            *(double *)field = 0;
        return 0;
    }
    case OPT_INT:
    case OPT_REAL:
    case OPT_REAL_ABOVE:
    case OPT_REAL_BETWEEN:
        (*i)++;
        if (read_number(spec->name, value, spec->min, spec->max, number_kind_of(spec), &v,
                        err) < 0)
            return -1;
        if (spec->kind == OPT_INT)
            *(int *)field = (int)v;
        else
            *(double *)field = v;
        return 0;
    case OPT_SEED:
        (*i)++;
        return read_seed(value, (uint64_t *)field, err);
    case OPT_MODE:
        (*i)++;
        return read_mode(value, (enum mode *)field, err);
    case OPT_QUALITY:
        (*i)++;
        return read_quality(value, (enum quality *)field, err);
    case OPT_OUTPUT:
        (*i)++;
        return read_output(value, field, &o->display, err);
    case OPT_STORE:
        (*i)++;
        return read_store(value, (int *)field, err);
    case OPT_FILE:
        (*i)++;
        if (value == NULL)
            return error_set(err, "", 0, "%s: expected a file name", spec->name);
        *(const char **)field = value;
        return 0;
    case OPT_CROP:
        for (int k = 0; k < 4; k++) {
            (*i)++;
            value = *i < argc ? argv[*i] : NULL;
            if (read_number(spec->name, value, spec->min, spec->max, NUMBER_WHOLE, &v, err) < 0)
                return -1;
            ((int *)field)[k] = (int)v;
        }
        o->has_crop = 1; /* apart from the values: 0 0 0 0 is an empty window, not none */
        return 0;
    }
    return -1;
}

/* The option given first on the command line (given[k]: the argv index of specs[k], 0
 * when absent) that means nothing for o->mode (option_spec.modes): -1 with *err naming
 * the modes it is for. */
static int check_modes(const struct options *o, const int given[N_SPECS], struct error *err)
{
    size_t first = N_SPECS;
    for (size_t k = 0; k < N_SPECS; k++)
        if (given[k] > 0 && !((specs[k].modes >> o->mode) & 1u) &&
            (first == N_SPECS || given[k] < given[first]))
            first = k;
    if (first == N_SPECS)
        return 0;
    char modes[64];
    mode_list(specs[first].modes, " or ", modes, sizeof modes);
    return error_set(err, "", 0, "%s: only for --mode %s (this render is --mode %s)",
                     specs[first].name, modes, mode_name(o->mode));
}

/* Words to apply: word[first ... n - 1]. */
struct words {
    char **word;
    int first, n;
};

/* Applies the words w to *o: options by specs[], any other word as the scene file; given[k]
 * becomes the index of the word that gave specs[k]. Returns 1 once --help or --version is
 * printed, -1 with *err filled on a bad word, else 0. */
static int apply_words(const struct words *w, struct options *o, int given[N_SPECS],
                       struct error *err)
{
    char **argv = w->word;
    int argc = w->n;
    for (int i = w->first; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0 ||
            strcmp(argv[i], "--manual") == 0) {
            print_help(strcmp(argv[i], "--manual") == 0 ? HELP_ROFF : HELP_TEXT);
            return 1;
        }
        if (strcmp(argv[i], "--version") == 0) {
            printf("photon %s\n", PHOTON_VERSION);
            return 1;
        }
        const struct option_spec *spec = find_spec(argv[i]);
        if (spec != NULL) {
            given[spec - specs] = i;
            if (apply_option(spec, argv, argc, &i, o, err) < 0)
                return -1;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            char hint[80];
            did_you_mean(argv[i], spec_at, N_SPECS, hint, sizeof hint);
            return error_set(err, "", 0, "unknown option '%s'%s (see photon --help)", argv[i],
                             hint);
        } else if (o->scene_path != NULL) {
            return error_set(err, "", 0, "more than one scene file: '%s' and '%s'",
                             o->scene_path, argv[i]);
        } else {
            o->scene_path = argv[i];
        }
    }
    return 0;
}

/* Applies the words of a layer that stands before the user's (a preset, --paper); name
 * heads the message of a bad word, which would be a defect of the table. */
static int apply_layer(const struct preset_words *layer, const char *name, struct options *o,
                       struct error *err)
{
    struct words list = {(char **)layer->word, 0, layer->n_words};
    int layer_given[N_SPECS] = {0};
    struct error inner;
    if (apply_words(&list, o, layer_given, &inner) != 0)
        return error_set(err, "", 0, "%s: %s", name, inner.message);
    return 0;
}

/* The defaults, the preset's words, --paper's, then the user's (argv[1 ...]): a first pass
 * reads the user's alone for the mode, quality and --paper (refusing a bad word first), the
 * second starts again from the defaults; given[] as the user's words leave it. */
static int apply_preset_and_words(int argc, char **argv, struct options *o,
                                  int given[N_SPECS], struct error *err)
{
    struct words user = {argv, 1, argc};
    option_defaults(o);
    int status = apply_words(&user, o, given, err);
    if (status != 0)
        return status;
    enum quality quality = o->quality;
    int paper = o->paper, user_specular_spp = o->specular_spp;
    struct preset_words preset, as_written;
    preset_words(o->mode, quality, &preset);
    paper_words(o->mode, paper, &as_written);
    option_defaults(o);
    char name[32];
    snprintf(name, sizeof name, "--quality %s", quality_name(quality));
    if (apply_layer(&preset, name, o, err) < 0 || apply_layer(&as_written, "--paper", o, err) < 0)
        return -1;
    status = apply_words(&user, o, given, err); /* 0: the first pass read the same words */
    /* A preset's --specular-spp gives way to a larger --spp of the user's: fewer samples
     * in the specular pixels than in the others is what the user did not ask for. */
    if (user_specular_spp == 0 && o->specular_spp > 0 && o->specular_spp < o->spp)
        o->specular_spp = o->spp;
    return status;
}

/* command_words.given (option_checks.h) over given[]: where the command line gave the
 * option called name, 0 when it did not. */
static int given_word(const void *given, const char *name)
{
    const struct option_spec *spec = find_spec(name);
    assert(spec != NULL);
    return ((const int *)given)[spec - specs];
}

int parse_options(int argc, char **argv, struct options *o, struct error *err)
{
    int given[N_SPECS] = {0};
    int status = apply_preset_and_words(argc, argv, o, given, err);
    if (status != 0)
        return status;
    if (o->scene_path == NULL)
        return error_set(err, "", 0, "no scene file given (see photon --help)");
    if (o->output[0] == '\0')
        default_output(o->scene_path, o->output);
    if ((o->reference == NULL) != (o->report == NULL))
        return error_set(err, "", 0, "--reference and --report go together");
    if (o->target_error > 0 && o->spp == 0 && o->mode != MODE_PPM2008) /* 2008: --passes */
        o->spp = MAX_SPP; /* the target ends the render, or the time limit */
    mode_defaults(o);
    if (o->cone > 0 && o->cone < 1)
        return error_set(err, "", 0, "--cone: k must be 0 (no filter) or at least 1");
    if (o->specular_spp == 0) /* spp <= MAX_SPP, so the product cannot overflow */
        o->specular_spp = (o->mode == MODE_JENSEN1996 || o->mode == MODE_JENSEN1994) &&
                                  !o->paper
                              ? (int)fmin(SPECULAR_SPP_FACTOR * o->spp, MAX_SPP)
                              : o->spp;
    struct command_words words = {given_word, given};
    if (check_combinations(o, &words, err) < 0)
        return -1;
    return check_modes(o, given, err); /* after the checks above, whose messages say why */
}

/* The options that change no pixel of the PFM: outputs, what is printed or shown, the
 * window, checkpoints and reports (they only look at the image), and the file of global
 * work, which holds what the render would compute itself, bit for bit (tests/test_merge.c).
 * options_hash() covers every other option. --time-limit is here because a hash cannot
 * capture it (the pixels depend on the machine's speed: tile.h records it apart);
 * --quality because its words are hashed themselves, as if spelled out. */
static const char *const outside_pixels[] = {
    "-o", "--crop", "--stats", "--progress", "--no-progress", "--exposure", "--reference",
    "--report", "--variance", "--error", "--block-error", "--checkpoint", "--time-limit",
    "--save-photons", "--load-photons", "--quality", "--paper",
};

static int changes_pixels(const struct option_spec *spec)
{
    for (size_t i = 0; i < sizeof outside_pixels / sizeof outside_pixels[0]; i++)
        if (strcmp(spec->name, outside_pixels[i]) == 0)
            return 0;
    return 1;
}

/* spec's value in o as text: exact for reals (17 significant digits round-trip a double),
 * and the same whatever order or spelling the command line used. */
static void option_text(const struct option_spec *spec, const struct options *o, char *text,
                        size_t size)
{
    const char *field = (const char *)o + spec->offset;
    switch (spec->kind) {
    case OPT_REAL:
    case OPT_REAL_ABOVE:
    case OPT_REAL_BETWEEN:
        snprintf(text, size, "%s=%.17g\n", spec->name, *(const double *)field);
        return;
    case OPT_SEED:
        snprintf(text, size, "%s=%llu\n", spec->name,
                 (unsigned long long)*(const uint64_t *)field);
        return;
    case OPT_MODE:
        snprintf(text, size, "%s=%s\n", spec->name, mode_name(*(const enum mode *)field));
        return;
    case OPT_FLAG:
    case OPT_INT:
    case OPT_STORE:
        snprintf(text, size, "%s=%d\n", spec->name, *(const int *)field);
        return;
    case OPT_OFF: /* its field is hashed under the option it turns off */
        text[0] = '\0';
        return;
    case OPT_QUALITY:
    case OPT_OUTPUT:
    case OPT_FILE:
    case OPT_CROP:
        break;
    }
    /* A file that changes pixels must have its bytes hashed where it is read, as the
     * scene's lines are (scene_hash_line); its name says nothing of them. */
    assert(!"--quality and the options naming files or the window are in outside_pixels[]");
    snprintf(text, size, "%s\n", spec->name);
}

uint64_t options_hash(const struct options *o, uint64_t h)
{
    char text[128];
    snprintf(text, sizeof text, "photon %s\n", PHOTON_VERSION);
    h = fnv1a(h, text, strlen(text));
    for (size_t i = 0; i < N_SPECS; i++)
        if (changes_pixels(&specs[i])) {
            option_text(&specs[i], o, text, sizeof text);
            h = fnv1a(h, text, strlen(text));
        }
    return h;
}
