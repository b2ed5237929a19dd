/*
 * main.c -- photon's command line: options -> scene -> mode -> outputs.
 *
 * Exit status: 0 on success, 2 for bad input (options, scene files, image files; the
 * message names file:line), 1 for a machine failure (out of memory, a failed write).
 * Every output is declared and checked before any work (check_outputs, base/output.h):
 * one that cannot be written there, or is another output or an input, is bad input; a
 * write that fails later (a full disk) is a machine failure, and no output is left.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/commands.h"
#include "app/option_values.h"
#include "app/options.h"
#include "app/report.h"
#include "app/suggest.h"
#include "app/tile.h"
#include "app/work_file.h"
#include "base/alloc.h"
#include "base/file_kind.h"
#include "base/output.h"
#include "image/error_image.h"
#include "modes/direct.h"
#include "modes/jensen1994.h"
#include "modes/jensen1996.h"
#include "modes/photons.h"
#include "modes/ppm2008.h"
#include "modes/pt.h"
#include "modes/sppm2009.h"

/* What one render command holds; released by finish_run() whatever happened. */
struct run {
    struct options o;
    struct scene *scene;       /* owned */
    struct image *reference;   /* owned, or NULL without --reference */
    struct report report;      /* open when reference != NULL */
    struct render_settings rs;
    struct render_counters counters;
    struct render_result result;
    struct photon_stats photon_stats;   /* --mode photons only */
    struct ppm_stats ppm_stats;         /* --mode 2008 and 2009 only */
    struct jensen1994_stats stats_1994; /* --mode 1994 only */
    struct jensen1996_stats stats_1996; /* --mode 1996 only */
    struct global_work work;           /* the photon modes' maps and cache (and 1994's
                                          illumination maps): owned, made by the mode or
                                          read by --load-photons                       */
    clock_t start;
    double seconds_build;
    double seconds_work_file;          /* reading or writing it                        */
    int checkpoint_failed;             /* a --checkpoint write failed: none is tried
                                          again, and the run ends with status 1         */
};

static double seconds_since(clock_t start)
{
    return (double)(clock() - start) / CLOCKS_PER_SEC;
}

/* The render window: the crop if one was given (checked against the image), else all. */
static int choose_window(const struct options *o, int width, int height,
                         struct render_settings *rs, struct error *err)
{
    int whole[4] = {0, 0, width, height};
    const int *w = o->has_crop ? o->crop : whole;
    if (!(w[0] < w[2] && w[2] <= width && w[1] < w[3] && w[3] <= height))
        return error_set(err, "", 0,
                         "--crop %d %d %d %d: need X0 < X1 <= %d and Y0 < Y1 <= %d (the image)",
                         w[0], w[1], w[2], w[3], width, height);
    rs->x0 = w[0];
    rs->y0 = w[1];
    rs->x1 = w[2];
    rs->y1 = w[3];
    return 0;
}

/* Progress is shown when asked for, or by default when the environment looks like an
 * interactive terminal: C99 cannot ask whether stderr is one, so TERM stands in for it.
 * Its form, a log's lines or a line in place, is chosen by base/progress.h. */
static int show_progress(int requested)
{
    if (requested >= 0)
        return requested;
    const char *term = getenv("TERM");
    return term != NULL && strcmp(term, "dumb") != 0 && getenv("CI") == NULL;
}

/* Reads the scene (a scene file, or an NFF file by its .nff name) and the reference, fixes
 * the settings and builds the BVH. */
static int prepare_run(struct run *run, struct error *err)
{
    const struct options *o = &run->o;
    run->scene = scene_load(o->scene_path, err);
    if (run->scene == NULL)
        return -1;
    int width = o->width > 0 ? o->width : run->scene->width;
    int height = o->height > 0 ? o->height : run->scene->height;
    run->rs.seed = o->seed;
    run->rs.spp = o->spp;
    run->rs.specular_spp = o->specular_spp;
    run->rs.time_limit = o->time_limit;
    run->rs.max_depth = o->max_depth >= 0 ? o->max_depth
                        : o->mode == MODE_DIRECT ? DIRECT_MAX_DEPTH
                                                 : MAX_DEPTH_LIMIT; /* roulette ends paths */
    run->rs.progress = show_progress(o->progress);
    run->rs.adaptive_error = o->adaptive;
    run->rs.min_spp = ADAPTIVE_MIN_SPP;
    run->rs.error_confidence = o->error != NULL || o->target_error > 0 ? o->confidence : 0.0;
    run->rs.target_error = o->target_error;
    if (choose_window(o, width, height, &run->rs, err) < 0)
        return -1;
    double eye_rays = (double)(run->rs.x1 - run->rs.x0) * (run->rs.y1 - run->rs.y0) * o->spp;
    if (o->mode == MODE_PPM2008 && eye_rays > PPM_MAX_EYE_RAYS)
        return error_set(err, "", 0, "--spp: %.0f eye rays (pixels x spp) exceed --mode 2008's "
                                     "limit of %d (each leaves a hit point of ~300 bytes)",
                         eye_rays, PPM_MAX_EYE_RAYS);
    if (o->reference != NULL) {
        run->reference = image_read(o->reference, err);
        if (run->reference == NULL)
            return error_set(err, err->file, err->line, "%s (--reference)", err->message);
        if (report_open(&run->report, o->report, run->reference, width, height, &run->rs,
                        err) < 0)
            return -1;
    }
    scene_finish(run->scene, width, height);
    if (run->scene->n_lights == 0) /* the sky is a light too (scene.h) */
        message_print("photon: warning: %s has no light (no light line, no emitting "
                      "material, no background): every mode renders it black", o->scene_path);
    run->seconds_build = seconds_since(run->start);
    return 0;
}

/* What made the pixels: the scene's lines and the options that change them (tile.h). */
static uint64_t render_hash(const struct run *run)
{
    return options_hash(&run->o, run->scene->source_hash);
}

/* With --crop, the record beside the PFM that lets photon merge place it (app/tile.h). */
static int write_tile_record(const struct run *run, struct error *err)
{
    struct tile_record r;
    r.x0 = run->rs.x0;
    r.y0 = run->rs.y0;
    r.x1 = run->rs.x1;
    r.y1 = run->rs.y1;
    r.width = run->scene->width;
    r.height = run->scene->height;
    r.hash = render_hash(run);
    r.pixels = tile_pixels_hash(run->result.image);
    r.time_limit = run->o.time_limit;
    return tile_record_write(run->o.output, &r, err);
}

/* --block-error: the block statement of the image's error image (image/error_image.h). */
static int write_block_error(const struct run *run, struct error *err)
{
    const struct render_result *r = &run->result;
    struct stated_error stated = {r->error, r->bias, r->block_noise, r->block_bias};
    struct image *blocks = block_error_image(r->image, &stated, run->rs.x0, run->rs.y0);
    int status = image_write(run->o.block_error, blocks, err); /* .exr or PFM */
    image_free(blocks);
    return status;
}

/* -o's PFM or OpenEXR file (the name ends in .pfm or .exr: read_output) and the display
 * image beside it, the variance and, for a crop, its record; put in place together by
 * render_command(). A whole render writes no record, and removes one an earlier crop left
 * (tile.h). */
static int write_outputs(struct run *run, struct error *err)
{
    const struct options *o = &run->o;
    if (image_write_pair(o->output, o->display, run->result.image, o->exposure, err) < 0)
        return -1;
    if (o->variance != NULL && image_write(o->variance, run->result.variance, err) < 0)
        return -1;
    if (o->error != NULL && image_write(o->error, run->result.error, err) < 0)
        return -1;
    if (o->block_error != NULL && write_block_error(run, err) < 0)
        return -1;
    if (o->has_crop && write_tile_record(run, err) < 0)
        return -1;
    clock_t start = clock();
    if (o->save_photons != NULL &&
        work_file_write(o->save_photons, render_hash(run), &run->work, err) < 0)
        return -1;
    run->seconds_work_file += seconds_since(start);
    return 0;
}

/* --checkpoint: the image so far, written over -o's files. A failed write is reported
 * once and no checkpoint is tried again (a full disk would print the same line at every
 * one); the render goes on to its final write, and the run ends with status 1. */
static double write_snapshot(void *context, const struct image *image, long long work,
                             double seconds)
{
    (void)work;
    (void)seconds;
    clock_t start = clock();
    struct run *run = context;
    const struct options *o = &run->o;
    struct error err;
    if (run->checkpoint_failed)
        return 0;
    if (image_write_pair(o->output, o->display, image, o->exposure, &err) < 0 ||
        outputs_publish(&err) < 0) {
        error_print(&err);
        fprintf(stderr, "photon: --checkpoint: no further checkpoint is written; the "
                "render goes on to its final image\n");
        run->checkpoint_failed = 1;
    }
    return seconds_since(start);
}

static void print_photon_stats(const struct photon_stats *ps)
{
    fprintf(stderr, "photons_emitted=%zu\nphotons_stored=%zu\nbytes_per_photon=%.2f\n",
            ps->photons_emitted, ps->photons_stored, ps->bytes_per_photon);
    fprintf(stderr, "seconds_photons=%.3f\nseconds_balance=%.3f\nmax_radius=%.6g\n",
            ps->seconds_photons, ps->seconds_balance, ps->max_radius);
    fprintf(stderr, "photon_rays=%llu\n", ps->photon_rays);
}

static void print_ppm_stats(const struct ppm_stats *ps)
{
    fprintf(stderr, "hit_points=%zu\nbytes_per_hit_point=%zu\nhit_members=%zu\npasses=%ld\n",
            ps->hit_points, ps->bytes_per_hit_point, ps->hit_members, ps->passes);
    fprintf(stderr, "photons_emitted=%zu\nphoton_rays=%llu\n", ps->photons_emitted,
            ps->photon_rays);
    fprintf(stderr, "seconds_ray_pass=%.3f\nseconds_photons=%.3f\n", ps->seconds_ray_pass,
            ps->seconds_photons);
    fprintf(stderr, "initial_mean_radius=%.6g\nmean_radius=%.6g\n", ps->initial_mean_radius,
            ps->mean_radius);
}

static void print_jensen1996_stats(const struct jensen1996_stats *stats)
{
    unsigned long long tests = stats->shadow_rays + stats->shadow_rays_avoided;
    fprintf(stderr, "photons_emitted=%zu\nphoton_rays=%llu\n", stats->photons_emitted,
            stats->photon_rays);
    fprintf(stderr, "photons_global=%zu\nphotons_caustic=%zu\nphotons_shadow=%zu\n",
            stats->photons_global, stats->photons_caustic, stats->photons_shadow);
    fprintf(stderr, "bytes_global_map=%zu\nbytes_caustic_map=%zu\nbytes_visibility_maps=%zu\n",
            stats->bytes_global_map, stats->bytes_caustic_map, stats->bytes_visibility_maps);
    fprintf(stderr, "seconds_photons=%.3f\nseconds_cache=%.3f\nseconds_final_pass=%.3f\n",
            stats->seconds_photons, stats->seconds_cache, stats->seconds_final_pass);
    fprintf(stderr, "shadow_rays=%llu\nshadow_rays_avoided=%llu\n", stats->shadow_rays,
            stats->shadow_rays_avoided);
    fprintf(stderr, "shadow_rays_avoided_fraction=%.4f\n",
            tests > 0 ? (double)stats->shadow_rays_avoided / (double)tests : 0.0);
    fprintf(stderr, "cache_records=%zu\nbytes_cache=%zu\ngathers=%llu\ngather_fallbacks=%llu\n",
            stats->cache_records, stats->bytes_cache, stats->gathers, stats->gather_fallbacks);
    fprintf(stderr, "gather_rays=%llu\nstrata=%dx%d\n", stats->gather_rays, stats->strata_theta,
            stats->strata_phi);
    fprintf(stderr, "precomputed_records=%zu\nbytes_precomputed=%zu\nseconds_precompute=%.3f\n",
            stats->precomputed_records, stats->bytes_precomputed, stats->seconds_precompute);
    fprintf(stderr, "precomputed_reads=%llu\nglobal_estimates=%llu\n", stats->precomputed_reads,
            stats->global_estimates);
}

/* The paper's Fig. 9 (photons stored, light rays, irradiance-gradient rays, shadow rays,
 * times) and the rest of the render's figures. */
static void print_jensen1994_stats(const struct jensen1994_stats *stats)
{
    fprintf(stderr, "photons_emitted=%zu\nphoton_rays=%llu\n", stats->photons_emitted,
            stats->photon_rays);
    fprintf(stderr, "photons_stored=%zu\nphotons_caustic=%zu\nphotons_glossy=%zu\n"
            "bytes_photon_map=%zu\n", stats->photons_stored, stats->photons_caustic,
            stats->photons_glossy, stats->bytes_photon_map);
    fprintf(stderr, "bytes_caustic_photons=%zu\n", stats->bytes_caustic_photons);
    fprintf(stderr, "bytes_per_photon=%.1f\n",
            stats->photons_stored > 0
                ? (double)stats->bytes_photon_map / stats->photons_stored
                : 0.0);
    fprintf(stderr, "projection_maps=%zu\nprojection_marked=%.4f\nbytes_projection_maps=%zu\n",
            stats->projection_maps, stats->projection_marked, stats->bytes_projection_maps);
    fprintf(stderr, "illumination_maps=%zu\nillumination_di_elements=%zu\n",
            stats->illumination_maps, stats->illumination_di_elements);
    fprintf(stderr, "illumination_ci_maps=%zu\nbytes_illumination_maps=%zu\n",
            stats->illumination_ci_maps, stats->bytes_illumination_maps);
    fprintf(stderr, "seconds_photons=%.3f\nseconds_cache=%.3f\nseconds_final_pass=%.3f\n",
            stats->seconds_photons, stats->seconds_cache, stats->seconds_final_pass);
    fprintf(stderr, "cache_records=%zu\nbytes_cache=%zu\ngradient_rays=%llu\n",
            stats->cache_records, stats->bytes_cache, stats->gradient_rays);
    fprintf(stderr, "gather_fallbacks=%llu\nshadow_rays=%llu\nstrata=%dx%d\n",
            stats->gather_fallbacks, stats->shadow_rays, stats->strata_theta,
            stats->strata_phi);
    fprintf(stderr, "precomputed_records=%zu\nbytes_precomputed=%zu\nseconds_precompute=%.3f\n",
            stats->precomputed_records, stats->bytes_precomputed, stats->seconds_precompute);
}

/* What the error image states (image/error_image.h): the relmse it expects against the
 * truth, and the share of ERROR_BLOCK-wide blocks, dark ones aside, whose bound at the
 * confidence is within 1% and 3% of their mean. */
static void print_error_stats(const struct render_result *result, double confidence, int x0,
                              int y0)
{
    struct stated_error stated = {result->error, result->bias, result->block_noise,
                                  result->block_bias};
    struct error_summary s = error_summary(result->image, &stated, confidence, x0, y0);
    fprintf(stderr, "confidence=%.6g\nestimated_relmse=%.6g\nbounded_blocks=%d\n",
            confidence, s.relmse, s.n_blocks);
    fprintf(stderr, "blocks_within_1pct=%.4f\nblocks_within_3pct=%.4f\n",
            s.n_blocks > 0 ? (double)s.within_1 / s.n_blocks : 0.0,
            s.n_blocks > 0 ? (double)s.within_3 / s.n_blocks : 0.0);
}

static void print_stats(const struct run *run)
{
    const struct scene *scene = run->scene;
    const struct render_counters *c = &run->counters;
    fprintf(stderr, "mode=%s\nseconds_total=%.3f\nseconds_build=%.3f\nseconds_render=%.3f\n",
            mode_name(run->o.mode), seconds_since(run->start), run->seconds_build,
            run->result.seconds);
    fprintf(stderr, "rays=%llu\nnonfinite_samples=%llu\n", c->rays, c->nonfinite_samples);
    if (run->o.save_photons != NULL || run->o.load_photons != NULL)
        fprintf(stderr, "seconds_work_file=%.3f\n", run->seconds_work_file);
    fprintf(stderr, "objects=%zu\nlights=%zu\nbvh_nodes=%zu\nbytes_geometry=%zu\n",
            geometry_primitive_count(scene->geometry), scene->n_lights,
            geometry_bvh_nodes(scene->geometry), geometry_bytes(scene->geometry));
    /* the most payload the x-allocators held at once, up to this line (base/alloc.h) */
    fprintf(stderr, "bytes_peak=%zu\n", alloc_bytes_peak());
    /* spp: the samples of a pixel (the passes that ran, at most --spp); pixels that see a
     * light through mirrors or glass take specular_spp (render.h), shown apart: the
     * samples taken, at most the passes that ran (fewer after a --time-limit stop) */
    int spp = c->passes < run->rs.spp ? c->passes : run->rs.spp;
    fprintf(stderr, "width=%d\nheight=%d\nspp=%d\nseed=%llu\n", scene->width, scene->height,
            spp, (unsigned long long)run->o.seed);
    int progressive = run->o.mode == MODE_PPM2008 || run->o.mode == MODE_SPPM2009;
    if (!progressive)
        fprintf(stderr, "specular_spp=%d\nspecular_pixels=%zu\n",
                c->passes < run->rs.specular_spp ? c->passes : run->rs.specular_spp,
                c->specular_pixels);
    double pixels = (double)(run->rs.x1 - run->rs.x0) * (double)(run->rs.y1 - run->rs.y0);
    if (!progressive)
        fprintf(stderr, "samples_per_pixel=%.3f\n", (double)c->samples / pixels);
    if (run->o.mode == MODE_PHOTONS)
        print_photon_stats(&run->photon_stats);
    if (progressive)
        print_ppm_stats(&run->ppm_stats);
    if (run->o.mode == MODE_JENSEN1994)
        print_jensen1994_stats(&run->stats_1994);
    if (run->o.mode == MODE_JENSEN1996)
        print_jensen1996_stats(&run->stats_1996);
    if (run->result.error != NULL)
        print_error_stats(&run->result, run->o.confidence, run->rs.x0, run->rs.y0);
    if (run->o.target_error > 0)
        fprintf(stderr, "target_blocks=%d\ntarget_blocks_within=%d\n", c->target_blocks,
                c->target_within);
}

/* The settings both progressive modes read, from the options. */
static struct progressive_settings progressive_settings(const struct options *o,
                                                        const struct checkpoint *report,
                                                        const struct checkpoint *snapshot)
{
    struct progressive_settings ps;
    ps.photons_per_pass = (size_t)o->photons_per_pass;
    ps.passes = o->passes;
    ps.alpha = o->alpha;
    ps.radius = o->radius;
    ps.footprints = o->footprints;
    ps.fit_radius = o->fit_radius;
    ps.facing_test = o->facing_test;
    ps.turn_photon_directions = o->turn_photon_directions;
    ps.direct_light_samples = o->direct_light_samples;
    ps.report = report;
    ps.snapshot_every = o->checkpoint;
    ps.snapshot = o->checkpoint > 0 ? snapshot : NULL;
    return ps;
}

/* A density estimate divides the photons within its radius by one disc's area, so where
 * many small surfaces share that radius it counts the neighbours' photons as the surface's
 * own: a sphere flake's spheres go down to a 3^LEVELS-th of its radius, and from
 * FINE_FLAKE_LEVELS on the modes that read photon maps render it and what it lights too
 * bright at their defaults, by more as the flake deepens and less as the photons grow
 * (reference/suite.md's consistency table). The progressive modes' radii shrink below any
 * sphere, and pt has no radius. */
#define FINE_FLAKE_LEVELS 4
static void warn_fine_flake(const struct scene *scene, const char *mode)
{
    if (scene->sphereflake_levels >= FINE_FLAKE_LEVELS)
        fprintf(stderr, "photon: warning: %s's photon estimates span many of a sphere "
                "flake's spheres (%d levels, down to 1/%.0f of its radius) and count their "
                "photons against one disc's area: the flake and what it lights render too "
                "bright; pt has no radius, and 2008's and 2009's shrink below its spheres\n",
                mode, scene->sphereflake_levels, pow(3.0, scene->sphereflake_levels));
}

/* Renders with the chosen mode; the image is NULL (and *err filled) on failure. Each
 * switch becomes the mode's setting of the same name and sense (--exclude-rim-photon,
 * exclude_rim), named by the departure's side as the option names it. */
static struct render_result render_mode(struct run *run, struct error *err)
{
    struct checkpoint report = {report_checkpoint, &run->report};
    const struct checkpoint *checkpoint = run->reference != NULL ? &report : NULL;
    int want_variance = run->o.variance != NULL;
    struct photon_settings ps;
    struct ppm_settings settings_2008 = ppm_settings_default();
    struct sppm_settings settings_2009 = sppm_settings_default();
    struct jensen1996_settings settings_1996 = jensen1996_settings_default();
    struct jensen1994_settings settings_1994 = jensen1994_settings_default();
    struct checkpoint snapshot = {write_snapshot, run};
    switch (run->o.mode) {
    case MODE_PT:
        if (pt_unreachable_light(run->scene) >= 0 && run->rs.error_confidence > 0) {
            struct render_result none = {NULL, NULL, NULL, NULL, NULL, NULL, 0.0};
            error_set(err, run->o.scene_path, 0, "%s: pt cannot find the caustics of this "
                      "scene's point lights, and its bound cannot state light it never "
                      "samples; 1996 and 2009 render them",
                      run->o.error != NULL ? "--error" : "--target-error");
            return none;
        }
        if (run->rs.error_confidence > 0 && pt_finds_caustics_by_chance(run->scene))
            fprintf(stderr, "photon: warning: pt finds light through mirrors and glass only "
                    "by chance, and where its samples have not found it yet, its error "
                    "bound does not state it: at 16 samples a pixel the bound missed such "
                    "light in 9-33%% of the blocks of the shipped scenes with caustics "
                    "(reference/suite.md), and more samples find more of it\n");
        if (pt_unreachable_light(run->scene) >= 0) {
            struct vec3 at = run->scene->lights[pt_unreachable_light(run->scene)].position;
            fprintf(stderr, "photon: warning: pt cannot find the caustics of point lights "
                    "(the first at %g %g %g): their light through mirrors or glass onto a "
                    "diffuse surface has probability zero and is missing from the image; "
                    "the photon modes render it\n", at.x, at.y, at.z);
        }
        return render_pt(run->scene, &run->rs, want_variance, checkpoint, &run->counters);
    case MODE_PHOTONS:
        fprintf(stderr, "photon: warning: --mode photons shows the global photon map's "
                "estimate directly (Jensen 1996, Fig. 4): blurred by its %d nearest photons "
                "and noisy at any photon count, it is a look at the map, not a converged "
                "image; use 1996 or 2009 for one\n", run->o.gather);
        if (run->rs.error_confidence > 0)
            fprintf(stderr, "photon: warning: --mode photons' error bound assumes that the "
                    "light changes smoothly within each estimate's disc and that its "
                    "photons' f_r are alike: it missed in 13-19%% of the blocks of 3 of the "
                    "30 shipped scenes, where a caustic's lines are finer than the disc "
                    "(cardioid-ring), a glossy floor reflects a few photons each "
                    "(cornell-glossy) and where the disc overhangs a floor's edge "
                    "(every-primitive; reference/suite.md)\n");
        warn_fine_flake(run->scene, "photons");
        ps.n_photons = (size_t)run->o.photons;
        ps.gather = (size_t)run->o.gather;
        ps.max_radius = run->o.max_radius;
        ps.cone_k = run->o.cone;
        ps.exclude_rim = run->o.exclude_rim;
        ps.work = &run->work;
        return render_photons(run->scene, &run->rs, &ps, want_variance, checkpoint,
                              &run->counters, &run->photon_stats, err);
    case MODE_JENSEN1994:
        warn_fine_flake(run->scene, "1994");
        settings_1994.n_photons = (size_t)run->o.photons;
        settings_1994.gather = (size_t)run->o.gather;
        settings_1994.max_radius = run->o.max_radius;
        settings_1994.differential_run = run->o.differential_run;
        settings_1994.exclude_rim = run->o.exclude_rim;
        settings_1994.caustic_radius_fraction = run->o.caustic_radius_fraction;
        settings_1994.gather_rays = run->o.gather_rays;
        settings_1994.cache_accuracy = run->o.cache_accuracy;
        settings_1994.light_samples = run->o.light_samples;
        settings_1994.both_lobes = run->o.both_lobes;
        settings_1994.bounded_reach = run->o.bounded_reach;
        settings_1994.glossy_photons = run->o.glossy_photons;
        settings_1994.lobe_lights = run->o.lobe_lights;
        settings_1994.precomputed_irradiance = run->o.precomputed_irradiance;
        settings_1994.gradient_limit = run->o.gradient_limit;
        settings_1994.projection_maps = run->o.projection_maps;
        settings_1994.illumination_maps = run->o.illumination_maps;
        settings_1994.work = &run->work;
        return render_jensen1994(run->scene, &run->rs, &settings_1994, want_variance,
                                 &run->counters, &run->stats_1994, err);
    case MODE_JENSEN1996:
        warn_fine_flake(run->scene, "1996");
        settings_1996.global_photons = (size_t)run->o.photons;
        settings_1996.caustic_photons = (size_t)run->o.caustic_photons;
        settings_1996.global_gather = (size_t)run->o.gather;
        settings_1996.caustic_gather = (size_t)run->o.caustic_gather;
        settings_1996.max_radius = run->o.max_radius;
        settings_1996.cone_k = run->o.cone;
        settings_1996.exclude_rim = run->o.exclude_rim;
        settings_1996.caustic_radius_fraction = run->o.caustic_radius_fraction;
        settings_1996.gather_rays = run->o.gather_rays;
        settings_1996.glossy_rays = run->o.glossy_rays;
        settings_1996.cache_accuracy = run->o.cache_accuracy;
        settings_1996.accurate_distance = run->o.accurate_distance;
        settings_1996.accurate_weight = run->o.accurate_weight;
        settings_1996.shadow_rays = run->o.shadow_rays;
        settings_1996.one_map = run->o.one_map;
        settings_1996.precomputed_irradiance = run->o.precomputed_irradiance;
        settings_1996.disc_coverage = run->o.disc_coverage;
        settings_1996.both_lobes = run->o.both_lobes;
        settings_1996.glossy_corner = run->o.glossy_corner;
        settings_1996.corner_photons = run->o.corner_photons;
        settings_1996.bounded_reach = run->o.bounded_reach;
        settings_1996.gradient_limit = run->o.gradient_limit;
        settings_1996.report = checkpoint;
        settings_1996.work = &run->work;
        return render_jensen1996(run->scene, &run->rs, &settings_1996, want_variance,
                                 &run->counters, &run->stats_1996, err);
    case MODE_PPM2008: {
        int glossy = ppm_glossy_material(run->scene);
        if (glossy >= 0)
            message_print("photon: warning: 2008's hit points estimate glossy lobes (the "
                          "first in material '%s') from photons, whose few hits near a "
                          "narrow lobe's peak speckle the image and fade slowly with the "
                          "passes; 2009 follows those lobes from the eye",
                          run->scene->materials[glossy].name);
        settings_2008.progressive = progressive_settings(&run->o, checkpoint, &snapshot);
        settings_2008.caustic_footprints = run->o.caustic_footprints;
        settings_2008.merge_hit_points = run->o.merge_hit_points;
        settings_2008.resample_emission = run->o.resample_emission;
        return render_ppm(run->scene, &run->rs, &settings_2008, &run->counters,
                          &run->ppm_stats);
    }
    case MODE_SPPM2009:
        settings_2009.progressive = progressive_settings(&run->o, checkpoint, &snapshot);
        settings_2009.disc_coverage = run->o.disc_coverage;
        settings_2009.follow_glossy_lobes = run->o.follow_glossy_lobes;
        return render_sppm(run->scene, &run->rs, &settings_2009, &run->counters,
                           &run->ppm_stats);
    case MODE_DIRECT:
        break;
    }
    return render_direct(run->scene, &run->rs, want_variance, checkpoint, &run->counters);
}

/* Every file the render will write, declared and checked before any work (output.h). */
static int check_outputs(const struct options *o, struct error *err)
{
    image_declare_pair(o->output, o->display, "-o",
                       o->display == DISPLAY_PPM ? "the PPM beside -o" : "the PNG beside -o");
    if (o->variance != NULL)
        output_declare(o->variance, "--variance");
    if (o->error != NULL)
        output_declare(o->error, "--error");
    if (o->block_error != NULL)
        output_declare(o->block_error, "--block-error");
    if (o->report != NULL)
        output_declare(o->report, "--report");
    if (o->save_photons != NULL)
        output_declare(o->save_photons, "--save-photons");
    if (o->has_crop)
        tile_record_declare(o->output);
    return outputs_check(err);
}

/* With --target-error: the blocks that ended short of it (the time limit or --spp came
 * first), named by the first. */
static void report_target(const struct run *run)
{
    const struct render_counters *c = &run->counters;
    if (run->o.target_error == 0 || c->target_within == c->target_blocks)
        return;
    int progressive = run->o.mode == MODE_PPM2008 || run->o.mode == MODE_SPPM2009;
    fprintf(stderr, "photon: --target-error %g: %d of %d blocks not within it after %ld "
            "%s, the first at (%d, %d)\n", run->o.target_error,
            c->target_blocks - c->target_within, c->target_blocks,
            progressive ? run->ppm_stats.passes : (long)c->passes,
            progressive ? "passes" : "samples per pixel", c->target_missed_x,
            c->target_missed_y);
}

static int render_command(struct run *run, struct error *err)
{
    if (check_outputs(&run->o, err) < 0 || prepare_run(run, err) < 0)
        return error_exit_status(err);
    clock_t start = clock();
    if (run->o.load_photons != NULL &&
        work_file_read(run->o.load_photons, render_hash(run), &run->work, err) < 0)
        return 2;
    run->seconds_work_file = seconds_since(start);
    run->result = render_mode(run, err);
    if (run->result.image == NULL)
        return 2;
    report_target(run);
    if (write_outputs(run, err) < 0 ||
        (run->reference != NULL && report_close(&run->report, err) < 0) ||
        outputs_publish(err) < 0 || (!run->o.has_crop && tile_record_remove(run->o.output,
                                                                             err) < 0))
        return 1; /* every output could be created before the render: a failed write */
    if (run->o.stats)
        print_stats(run);
    return run->checkpoint_failed ? 1 : 0; /* its outputs are whole; a checkpoint failed */
}

static void finish_run(struct run *run)
{
    if (run->reference != NULL)
        report_abandon(&run->report); /* a no-op once closed */
    render_result_free(&run->result);
    global_work_free(&run->work);
    image_free(run->reference);
    scene_free(run->scene);
}

/* The commands beside rendering (app/commands.h): photon NAME ARGS... runs
 * run_subcommand() on argv + 1. For the near miss of a command (app/suggest.h). */
static const char *command_at(size_t i)
{
    return commands[i].name;
}

/* A first word that is no file but nearly a command ("comapre") is a mistyped command,
 * not a scene: -1 with *err naming the command, else 0. */
static int refuse_near_command(int argc, char **argv, struct error *err)
{
    if (argc < 2 || argv[1][0] == '-' || file_is_there(argv[1]))
        return 0;
    const char *command = nearest_name(argv[1], command_at, N_COMMANDS);
    return command == NULL ? 0
                           : error_set(err, "", 0, "'%s' is neither a scene file nor a "
                                       "command: did you mean 'photon %s'?", argv[1],
                                       command);
}

/* Runs command c on its words (argv[0] its name), each --NAME=VALUE of its options two
 * words, as a render's are (base/option_equals.h); its exit status, 2 for an '=' refused. */
static int run_subcommand(const struct command *c, int argc, char **argv)
{
    char **split;
    int split_argc = 0;
    struct error err;
    int status = split_equals(c->name, argc, argv, c->options, &split, &split_argc, &err);
    if (status < 0)
        error_print(&err);
    else
        status = c->run(split_argc, split);
    xfree(split);
    return status < 0 ? 2 : status;
}

/* Runs the command line: a command beside rendering, or a render; its exit status. */
static int run_command(int argc, char **argv)
{
    for (size_t i = 0; argc > 1 && i < N_COMMANDS; i++)
        if (strcmp(argv[1], commands[i].name) == 0)
            return run_subcommand(&commands[i], argc - 1, argv + 1);
    struct run run;
    struct error err;
    memset(&run, 0, sizeof run);
    run.scene = NULL;
    run.reference = NULL;
    run.result.image = NULL;
    run.result.variance = NULL;
    run.result.error = NULL;
    run.result.bias = NULL;
    run.result.block_noise = NULL;
    run.result.block_bias = NULL;
    run.work.maps = NULL;
    run.work.records = NULL;
    run.work.illumination = NULL;
    run.start = clock();
    if (refuse_near_command(argc, argv, &err) < 0) {
        error_print(&err);
        return 2;
    }
    int parsed = parse_options(argc, argv, &run.o, &err);
    if (parsed != 0) {
        if (parsed < 0)
            error_print(&err);
        return parsed < 0 ? 2 : 0;
    }
    int status = render_command(&run, &err);
    if (status != 0)
        error_print(&err);
    finish_run(&run);
    return status;
}

/* Every command's status, and 1 when what it printed on the standard output was lost. */
int main(int argc, char **argv)
{
    return standard_output_status(run_command(argc, argv));
}
