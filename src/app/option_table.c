/*
 * app/option_table.c -- the table of the render command's options (option_table.h).
 */
#include "option_table.h"

#include "../image/image.h"
#include "../modes/jensen1994.h"
#include "../modes/jensen1996.h"
#include "../modes/photons.h"
#include "../modes/ppm2008.h"
#include "../modes/progressive.h"
#include "../modes/render.h"
#include "../photon/trace.h"

#define FIELD(f) offsetof(struct options, f)

const struct option_spec option_specs[] = {
    {"--mode", OPT_MODE, FIELD(mode), 0, 0, "NAME",
     "rendering mode: direct, pt, photons, 1994, 1996, 2008 or 2009 (default pt)", FOR_ALL},
    {"--quality", OPT_QUALITY, FIELD(quality), 0, 0, "NAME",
     "preview, default or reference: the mode's preset of options (listed below), applied "
     "before the other options given (default default)", FOR_ALL},
    {"--paper", OPT_FLAG, FIELD(paper), 0, 0, "",
     "the paper as written: every departure of the mode off, before the other options "
     "given (listed below: a departure's switch is --NAME, the default, and --no-NAME, the "
     "paper's; or the paper's value of a number)", FOR_ALL},
    {"-o", OPT_OUTPUT, FIELD(output), 0, 0, "FILE.pfm|.exr|.png|.ppm",
     "output: FILE.pfm (linear radiance) and FILE.png beside it for display; -o FILE.exr "
     "writes OpenEXR in place of the PFM, -o FILE.ppm FILE.ppm in place of the PNG "
     "(default: SCENE's name)", FOR_ALL},
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
     "also writes FILE.pfm.window (FILE.exr.window) for photon merge", FOR_ALL},
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
    {"--reference", OPT_FILE, FIELD(reference), 0, 0, "REF.pfm|.exr",
     "with --report: the converged image to measure error against (whole-image size)", FOR_ALL},
    {"--report", OPT_FILE, FIELD(report), 0, 0, "FILE.csv",
     "write seconds,work,rmse,relmse at work 1, 2, 4, ... and at the end", FOR_ALL},
    {"--variance", OPT_FILE, FIELD(variance), 0, 0, "FILE.pfm|.exr",
     "also write each pixel's variance of the mean (needs --spp >= 2)", FOR_SAMPLES},
    {"--error", OPT_FILE, FIELD(error), 0, 0, "FILE.pfm|.exr",
     "also write each pixel's bound on |pixel - truth| at --confidence, from its samples' "
     "and its 5 x 5 neighbours' spread (needs --spp >= 16); 2008, 2009: from its passes' "
     "spread and, added, its photon estimates' bias, from discs of half the area (needs "
     "--passes >= 16); photons: the same from its map's 8 batches of photons",
     FOR_PT | FOR_PHOTONS | FOR_PROGRESSIVE},
    {"--block-error", OPT_FILE, FIELD(block_error), 0, 0, "FILE.pfm|.exr",
     "with --error: also write each 16 x 16 block's bound on |block mean - truth|, one pixel "
     "a block, for photon compare --test-block-error (not with --crop)",
     FOR_PT | FOR_PHOTONS | FOR_PROGRESSIVE},
    {"--confidence", OPT_REAL_BETWEEN, FIELD(confidence), 0, 1, "C",
     "the confidence of --error's bound: the truth is within it in a fraction C of the "
     "pixels (default 0.95)", FOR_PT | FOR_PHOTONS | FOR_PROGRESSIVE},
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
     "largest gathering radius: where photons are few an estimate takes those within it "
     "(default: 1/10 of the scene's diagonal)", FOR_PHOTON_MAPS},
    {"--no-max-radius", OPT_OFF, FIELD(max_radius), 0, 0, "",
     "no largest radius: an estimate's disc grows until it holds its photons (the papers')",
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
     "surface's edges where caustic photons are sparse; with --no-max-radius, the papers', "
     "no maximum bounds them)", FOR_1994 | FOR_1996},
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
     "rays sampling a glossy surface seen accurately (default 6, the paper's \"maximum of "
     "6\")", FOR_1996},
    {"--cache-accuracy", OPT_REAL, FIELD(cache_accuracy), 0, 10, "A",
     "irradiance cache accuracy a (Ward 1988); 1996 only: 0 = gather at every "
     "point, and the switches of a record's R (--bounded-reach, --gradient-limit) are "
     "refused (default 0.15)", FOR_1994 | FOR_1996},
    {"--accurate-distance", OPT_REAL, FIELD(accurate_distance), 0, 1e6, "F",
     "gather rays shorter than F radii of the estimate they reach are evaluated as "
     "accurately (the paper's \"small threshold\", its value not specified by the paper; "
     "their soft indirect light: --corner-photons; default 3)",
     FOR_1996},
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
     "gather rays read irradiance precomputed at every N-th global photon (1994: of the "
     "photon map) (Christensen 1999; default 16)", FOR_1994 | FOR_1996},
    {"--no-precomputed-irradiance", OPT_OFF, FIELD(precomputed_irradiance), 0, 0, "",
     "a radiance estimate at each gather ray's end (the paper's)", FOR_1994 | FOR_1996},
    {"--disc-coverage", OPT_FLAG, FIELD(disc_coverage), 0, 0, "",
     "records of precomputed irradiance (2009: a pixel's estimate) count the photons of "
     "their disc's plane, arrived from its side, over the part of the disc a surface "
     "covers, found by probe rays (2009: one a pass), in place of pi r^2 (the default); "
     "1996: refused with --no-precomputed-irradiance, which makes no records",
     FOR_1996 | FOR_2009},
    {"--no-disc-coverage", OPT_FLAG, FIELD(disc_coverage), 0, 0, "",
     "over the whole disc, pi r^2, as Eq. 3 (the paper's; 2009: every photon within r "
     "counts)", FOR_1996 | FOR_2009},
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
    {"--corner-photons", OPT_FLAG, FIELD(corner_photons), 0, 0, "",
     "the end of a gather ray shorter than --accurate-distance takes its soft indirect "
     "light from the global map's indirect photons (the default)", FOR_1996},
    {"--no-corner-photons", OPT_FLAG, FIELD(corner_photons), 0, 0, "",
     "from a final gather of its own, as accurate points do, whose rays are approximate "
     "(the paper's)", FOR_1996},
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
     "initial radius in pixel footprints at each hit point (default 4; the paper's "
     "example: 1); refused with --radius", FOR_PROGRESSIVE},
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
     "emission only from the --spp eye rays of the ray tracing pass, the paper's (its only "
     "eye rays)", FOR_2008},
    {"--facing-test", OPT_FLAG, FIELD(facing_test), 0, 0, "",
     "a photon counts only at hit points whose surface faces its own (the default; 2009's "
     "--disc-coverage holds such a test)", FOR_2008},
    {"--no-facing-test", OPT_FLAG, FIELD(facing_test), 0, 0, "",
     "every photon within R counts, as the paper's \"photons within the radius\"",
     FOR_2008},
    {"--turn-photon-directions", OPT_FLAG, FIELD(turn_photon_directions), 0, 0, "",
     "f_r sees a photon's direction turned by the rotation taking its surface's normal to "
     "the hit point's, so none within R falls below a curved surface's horizon (the "
     "default)", FOR_PROGRESSIVE},
    {"--no-turn-photon-directions", OPT_FLAG, FIELD(turn_photon_directions), 0, 0, "",
     "f_r of each photon's direction as it arrived, the papers'", FOR_PROGRESSIVE},
    {"--follow-glossy-lobes", OPT_FLAG, FIELD(follow_glossy_lobes), 0, 0, "",
     "an eye path samples a glossy lobe and goes on, as through a mirror, its hit point "
     "taking a surface's diffuse part alone (the default)", FOR_2009},
    {"--no-follow-glossy-lobes", OPT_FLAG, FIELD(follow_glossy_lobes), 0, 0, "",
     "the hit point at the first surface with a non-specular part, with its whole BRDF, "
     "the paper's", FOR_2009},
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
    {"--progress", OPT_FLAG, FIELD(progress), 0, 0, "",
     "show each phase's progress and wall-clock time left on stderr: to a file (ftell() "
     "works) a line at most every 10 s, else one line rewritten at most once a second "
     "(default: on when TERM names a terminal and CI is unset)", FOR_ALL},
    {"--no-progress", OPT_FLAG, FIELD(progress), 0, 0, "", "never show the progress line", FOR_ALL},
};

/* An array of -1 chars, which does not compile, unless N_OPTION_SPECS counts the rows. */
typedef char option_count_is_right[sizeof option_specs / sizeof option_specs[0] ==
                                   N_OPTION_SPECS ? 1 : -1];
