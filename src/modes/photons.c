/*
 * modes/photons.c -- `--mode photons`: the global photon map visualised directly, the
 * picture of Jensen 1996's Fig. 4.
 *
 * The algorithm, one call per step (render_photons):
 *   1. trace the global map: every photon stored at every non-delta surface it hits
 *      (direct, caustic and indirect photons; Sec. 3);
 *   2. balance it into a kd-tree (Sec. 3);
 *   3. for each pixel, follow the camera ray through ideal mirrors and glass; at the first
 *      surface with a non-delta part return its emission plus the radiance estimate of
 *      Eq. 3 (or Eq. 5 with the cone filter) from the nearest photons (Sec. 5).
 * Steps 1 and 2 are the render's global work: with --load-photons the map comes from a
 * file instead (photon/global_work.h), the same map node for node.
 * No direct lighting is computed: everything a diffuse surface shows comes from the
 * photons, which is why the picture is blotchy at low photon counts, and why its
 * brightness is right (the estimate is consistent) where it is not blotchy.
 * The two departures, which --paper undoes: each estimate leaves out the photon on its rim
 * (--exclude-rim-photon; photon/estimate.h says why), and stops at a maximum radius
 * (--max-radius, PHOTONS_RADIUS_FRACTION of the scene's diagonal by default), where the
 * paper's sphere grows until it holds its photons (--no-max-radius; src/modes/README.md,
 * Estimates).
 *
 * The estimate's scratch (struct nearest) is made once before render_pixels() and
 * reached through the mode struct: render_pixels() estimates one pixel at a time, so a
 * single scratch serves them all and the pixel loop allocates nothing. A renderer that
 * ran pixels in parallel would need one scratch per thread.
 */
#include "photons.h"

#include <string.h>
#include <time.h>

#include "../photon/estimate.h"
#include "../photon/trace.h"
#include "../scene/brdf.h"
#include "photons_error.h"
#include "surface.h"
#include "trace_progress.h"

struct photons_mode {
    const struct scene *scene;   /* borrowed                                            */
    const struct kdtree *map;    /* borrowed from render_photons(): the global map      */
    struct estimate_settings es; /* k, max_r2, cone filter                              */
    struct nearest *nn;          /* borrowed from render_photons(): the one scratch,
                                    overwritten by every estimate                       */
    int max_depth;               /* longest chain of specular bounces from the camera   */
    struct photons_error *error; /* borrowed, NULL without an error image: every
                                    estimate's batches go there (photons_error.h)       */
};

/* Eq. 3 / Eq. 5 at the surface s, seen along s->wo through the path weight beta. */
static struct vec3 estimate_at(const struct photons_mode *pm, const struct surface *s,
                               const struct shading_frame *frame, struct vec3 beta)
{
    struct estimate_point at;
    at.x = s->p;
    at.ng = s->ng;
    at.wo = s->wo;
    at.material = s->material;
    at.frame = frame;
    at.back = !s->front;
    if (pm->error == NULL)
        return radiance_estimate(pm->map, &at, &pm->es, pm->nn);
    struct estimate_batches batches;
    struct vec3 l = radiance_estimate_in_batches(pm->map, &at, &pm->es, pm->nn, &batches);
    photons_error_add_estimate(pm->error, beta, &batches);
    return l;
}

static struct vec3 photons_radiance(const void *mode, struct ray ray,
                                    const struct first_bounce *first, struct rng *rng,
                                    struct render_counters *counters)
{
    (void)first; /* its first bounce draws from the stream */
    const struct photons_mode *pm = mode;
    struct vec3 l = vec3_zero(), beta = vec3(1.0, 1.0, 1.0);
    for (int depth = 0;; depth++) {
        struct hit hit;
        counters->rays++;
        if (!scene_intersect(pm->scene, ray, INFINITY, &hit))
            return vec3_add(l, vec3_mul(beta, pm->scene->background));
        struct surface s = surface_at(pm->scene, &hit, vec3_neg(ray.dir));
        struct shading_frame frame = shading_frame_from_normal(s.ns, s.front,
                                                               TRANSPORT_RADIANCE);
        struct vec3 le = surface_emission(&s);
        if (brdf_has_non_delta(s.material))
            le = vec3_add(le, estimate_at(pm, &s, &frame, beta));
        l = vec3_add(l, vec3_mul(beta, le));
        if (!brdf_has_delta(s.material) || depth >= pm->max_depth ||
            !specular_bounce(&s, &frame, rng, &beta, &ray))
            return l;
    }
}

static void photons_sample_taken(const void *mode, size_t pixel, struct vec3 value,
                                 int counted)
{
    const struct photons_mode *pm = mode;
    photons_error_sample_taken(pm->error, pixel, value, counted);
}

/* The diagonal of the scene's bounding box, so the default limit scales with the scene;
 * HUGE_VAL, no limit, for a scene with no extent. */
static double box_diagonal(const struct scene *scene)
{
    struct aabb box = geometry_bounds(scene->geometry);
    double diagonal = vec3_length(vec3_sub(box.hi, box.lo));
    return isfinite(diagonal) && diagonal > 0 ? diagonal : HUGE_VAL;
}

double largest_radius(double max_radius, double diagonal)
{
    if (max_radius > 0)
        return max_radius;
    return max_radius == 0 ? HUGE_VAL : PHOTONS_RADIUS_FRACTION * diagonal;
}

struct max_radii max_radii_of(double max_radius, double caustic_fraction, double diagonal)
{
    double r = largest_radius(max_radius, diagonal);
    struct max_radii radii;
    radii.all_r2 = r * r;
    radii.caustic_r2 = radii.all_r2 * caustic_fraction * caustic_fraction;
    return radii;
}

/* Steps 1 and 2: the balanced global map, or NULL with *err filled. */
static struct kdtree *build_global_map(const struct scene *scene,
                                       const struct render_settings *rs,
                                       const struct photon_settings *ps,
                                       struct photon_stats *stats, struct error *err)
{
    struct trace_settings ts;
    memset(&ts, 0, sizeof ts);
    ts.seed = rs->seed;
    ts.pass = 0;
    ts.n_emit = ps->n_photons;
    ts.max_stored = MAX_PHOTONS;
    ts.store = PHOTON_MAP_GLOBAL;
    ts.max_depth = rs->max_depth;
    ts.targets = NULL;
    ts.projection = NULL;
    clock_t start = clock();
    struct trace_progress tp;
    trace_progress_begin(&tp, rs->progress, "global photon map", &ts);
    struct photon_trace traced;
    int failed = trace_photons(scene, &ts, &traced, err) < 0;
    trace_progress_end(&tp, !failed);
    if (failed)
        return NULL;
    stats->seconds_photons = cpu_seconds(start);
    stats->photons_emitted = traced.n_emitted;
    stats->photon_rays = traced.rays;
    start = clock();
    struct watched_progress balancing;
    watched_progress_begin(&balancing, rs->progress, "global photon map balancing",
                           KDTREE_BALANCE_STEPS(traced.n_photons), "steps");
    struct kdtree *map = balance_part(traced.photons, traced.n_photons, &balancing); /* takes
                                                                                    them */
    watched_progress_end(&balancing, 1);
    stats->seconds_balance = cpu_seconds(start);
    traced.photons = NULL;
    photon_trace_free(&traced);
    return map;
}

/* The global map: steps 1 and 2 into work->maps[0] when work is empty, else the map work
 * holds (loaded from a file). Borrowed from work; NULL with *err filled. */
static const struct kdtree *global_map(const struct scene *scene,
                                       const struct render_settings *rs,
                                       const struct photon_settings *ps,
                                       struct photon_stats *stats, struct error *err)
{
    struct global_work *work = ps->work;
    if (work->n_maps == 0) {
        struct kdtree *map = build_global_map(scene, rs, ps, stats, err);
        if (map == NULL)
            return NULL;
        global_work_add_maps(work, 1);
        work->maps[0] = map;
    } else if (work->n_maps != 1 || work->maps[0] == NULL || work->n_records != 0 ||
               work->illumination != NULL) {
        error_set(err, "", 0, "--load-photons: the file does not hold one photon map and "
                              "nothing else, as mode photons saves");
        return NULL;
    }
    const struct kdtree *map = work->maps[0];
    stats->photons_stored = map->n_photons;
    stats->bytes_per_photon = map->n_photons > 0
                                  ? (double)kdtree_bytes(map) / (double)map->n_photons
                                  : 0.0;
    return map;
}

/* The written window of an image of kept's window (freed); NULL stays NULL. */
static struct image *written_window(const struct kept_window *kept, struct image *img)
{
    if (img == NULL || (img->width == kept->out_width && img->height == kept->out_height))
        return img;
    struct image *written = image_window(img, kept->out_x0, kept->out_y0, kept->out_width,
                                         kept->out_height);
    image_free(img);
    return written;
}

/* A checkpoint that adds the photon pass's seconds to the render's and shows only the
 * written window before passing on. */
struct shifted_checkpoint {
    const struct checkpoint *inner;  /* borrowed                        */
    double seconds;                  /* added to every checkpoint's time */
    const struct kept_window *kept;  /* borrowed: the window rendered and the one written */
};

static double shifted_at(void *context, const struct image *mean, long long work,
                         double seconds)
{
    const struct shifted_checkpoint *sc = context;
    const struct kept_window *k = sc->kept;
    if (mean->width == k->out_width && mean->height == k->out_height)
        return sc->inner->at(sc->inner->context, mean, work, seconds + sc->seconds);
    struct image *written = image_window(mean, k->out_x0, k->out_y0, k->out_width,
                                         k->out_height);
    double spent = sc->inner->at(sc->inner->context, written, work, seconds + sc->seconds);
    image_free(written);
    return spent;
}

struct render_result render_photons(const struct scene *scene, const struct render_settings *rs,
                                    const struct photon_settings *ps, int want_variance,
                                    const struct checkpoint *checkpoint,
                                    struct render_counters *counters, struct photon_stats *stats,
                                    struct error *err)
{
    struct render_result result = {NULL, NULL, NULL, NULL, NULL, NULL, 0.0};
    memset(stats, 0, sizeof *stats);
    struct global_work own_work = {NULL, 0, NULL, 0, NULL}; /* without ps->work: traced, freed */
    struct photon_settings with_work = *ps;
    if (with_work.work == NULL)
        with_work.work = &own_work;
    const struct kdtree *map = global_map(scene, rs, &with_work, stats, err);
    if (map == NULL) {
        global_work_free(&own_work);
        return result;
    }
    stats->max_radius = largest_radius(ps->max_radius, box_diagonal(scene));
    struct photons_mode pm;
    pm.scene = scene;
    pm.map = map;
    pm.es.k = ps->gather;
    pm.es.max_r2 = stats->max_radius * stats->max_radius;
    pm.es.cone_k = ps->cone_k;
    pm.es.kinds = 0;
    pm.es.exclude_rim = ps->exclude_rim;
    pm.nn = nearest_create(ps->gather);
    pm.max_depth = rs->max_depth;
    int want_error = rs->error_confidence > 0;
    struct photons_error error;
    struct kept_window kept; /* without an error image, the window asked for */
    if (want_error) {
        photons_error_create(&error, rs, scene->width, scene->height);
        kept = error.kept;
    } else {
        kept_window_init(&kept, rs, scene->width, scene->height, 0);
    }
    pm.error = want_error ? &error : NULL;
    struct render_settings pixels = kept.grown;
    pixels.error_confidence = 0.0; /* the map's batches state the error, not the samples */
    struct radiance_estimator estimator;
    estimator.radiance = photons_radiance;
    estimator.mode = &pm;
    estimator.sample_taken = want_error ? photons_sample_taken : NULL;
    double photon_seconds = stats->seconds_photons + stats->seconds_balance;
    struct shifted_checkpoint shifted = {checkpoint, photon_seconds, &kept};
    struct checkpoint at_shifted = {shifted_at, &shifted};
    result = render_pixels(scene, &pixels, estimator, want_variance,
                           checkpoint != NULL ? &at_shifted : NULL, counters);
    result.seconds += photon_seconds;
    if (want_error) {
        clock_t start = clock();
        photons_error_result(&error, result.image, &result);
        result.seconds += cpu_seconds(start);
        photons_error_free(&error);
    }
    result.image = written_window(&kept, result.image);
    result.variance = written_window(&kept, result.variance);
    nearest_free(pm.nn);
    global_work_free(&own_work);
    return result;
}
