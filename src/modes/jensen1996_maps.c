/*
 * modes/jensen1996_maps.c -- pass 1 of `--mode 1996` (Jensen 1996, Sec. 3): constructing
 * the photon maps (jensen1996_maps.h).
 *
 * The global trace emits photons "towards all objects" and hands each stored photon to
 * one sink that sends it to the global map and, when it is a direct or shadow photon,
 * to its light's visibility map; the caustic trace emits towards bounding spheres of the
 * specular objects. Each trace is balanced into a kd-tree (photon/kdtree.h) as soon as it
 * is complete, the maps of one trace on one progress line, and the maps go to the render's
 * global work, which owns them from then on.
 */
#include "jensen1996_maps.h"

#include <string.h>

#include "../base/alloc.h"
#include "../photon/trace.h"
#include "../scene/emit.h"
#include "trace_progress.h"

/* Where the global trace's photons go: every photon but the shadow ones to the global
 * map, and the direct and shadow photons also to their light's visibility map, since a
 * direct photon of one light says nothing about another's shadow. Every step-th photon
 * of the global map is also a record of precomputed irradiance (Christensen 1999), kept
 * with the surface normal where it landed in place of its direction. */
struct global_sink {
    struct photon_trace global;
    struct photon_trace *visibility; /* n_lights of them, or NULL */
    struct photon_trace records;     /* empty when step is 0 */
    size_t step;                     /* settings->precomputed_irradiance */
};

static int store_record(struct global_sink *gs, const struct photon_event *e)
{
    if (gs->step == 0 || (gs->global.n_photons - 1) % gs->step != 0)
        return 0;
    struct photon_event record = *e;
    record.wi = e->normal;
    record.power = vec3_zero(); /* unused: the record's value is its irradiance */
    return photon_trace_store(&gs->records, MAX_PHOTONS, &record);
}

static int store_global(void *context, const struct photon_event *e)
{
    struct global_sink *gs = context;
    if (e->kind != PHOTON_SHADOW &&
        (photon_trace_store(&gs->global, MAX_PHOTONS, e) < 0 || store_record(gs, e) < 0))
        return -1;
    if (gs->visibility != NULL && (e->kind & (PHOTON_DIRECT | PHOTON_SHADOW)) &&
        photon_trace_store(&gs->visibility[e->light], MAX_PHOTONS, e) < 0)
        return -1;
    return 0;
}

/* The photons of every map the global trace made: the global map's, the records',
 * the visibility maps'. */
static size_t photons_stored(const struct global_sink *gs, size_t n_lights)
{
    size_t n = gs->global.n_photons + gs->records.n_photons;
    for (size_t l = 0; gs->visibility != NULL && l < n_lights; l++)
        n += gs->visibility[l].n_photons;
    return n;
}

/* traced's photons as a map (which takes them), the next part of balancing's line;
 * traced is left empty. */
static struct kdtree *balance_trace(struct photon_trace *traced,
                                    struct watched_progress *balancing)
{
    struct kdtree *map = balance_part(traced->photons, traced->n_photons, balancing);
    traced->photons = NULL;
    photon_trace_free(traced);
    return map;
}

static struct trace_settings photon_pass(const struct render_settings *rs, uint64_t pass,
                                         size_t n_emit, unsigned store)
{
    struct trace_settings ts;
    memset(&ts, 0, sizeof ts);
    ts.seed = rs->seed;
    ts.pass = pass;
    ts.n_emit = n_emit;
    ts.max_stored = MAX_PHOTONS;
    ts.store = store;
    ts.max_depth = rs->max_depth;
    ts.targets = NULL;
    ts.projection = NULL;
    ts.by_parts = 1; /* Eq. 2's split: caustics are light through f_r,s, glossy lobes too */
    return ts;
}

static int too_many_photons(struct error *err)
{
    return error_set(err, "", 0,
                     "photon map: more than %d photons would be stored; emit fewer photons or "
                     "follow fewer bounces (--max-depth)",
                     MAX_PHOTONS);
}

/* The global map "emitting photons towards all objects", and the visibility maps. With
 * one_map the caustic photons' share is emitted here too, so both variants spend the
 * same photons. */
static int build_global_map(const struct scene *scene, const struct render_settings *rs,
                            const struct jensen1996_settings *settings,
                            struct photon_maps *maps, struct jensen1996_stats *stats,
                            struct error *err)
{
    size_t n_emit =
        settings->global_photons + (settings->one_map ? settings->caustic_photons : 0);
    unsigned store = PHOTON_MAP_GLOBAL | (settings->shadow_rays ? 0 : PHOTON_SHADOW);
    struct trace_settings ts = photon_pass(rs, 0, n_emit < MAX_PHOTONS ? n_emit : MAX_PHOTONS,
                                           store);
    struct global_sink gs;
    memset(&gs, 0, sizeof gs);
    gs.global.photons = NULL;
    gs.visibility = NULL;
    gs.records.photons = NULL;
    gs.step = (size_t)settings->precomputed_irradiance;
    if (!settings->shadow_rays && scene->n_lights > 0)
        gs.visibility = xcalloc(scene->n_lights, sizeof *gs.visibility, "visibility maps");
    struct photon_sink sink = {store_global, &gs};
    struct trace_progress tp;
    trace_progress_begin(&tp, rs->progress, "global photon map", &ts);
    int failed = trace_photons_into(scene, &ts, &sink, &stats->photon_rays) < 0;
    trace_progress_end(&tp, !failed);
    stats->photons_emitted += ts.n_emit;
    struct watched_progress balancing;
    watched_progress_begin(&balancing, rs->progress, "global photon map balancing",
                           KDTREE_BALANCE_STEPS(photons_stored(&gs, scene->n_lights)), "steps");
    maps->global = balance_trace(&gs.global, &balancing);
    stats->photons_global = maps->global->n_photons;
    maps->records = gs.step > 0 ? balance_trace(&gs.records, &balancing) : NULL;
    if (gs.visibility != NULL) {
        maps->visibility = xcalloc(scene->n_lights, sizeof *maps->visibility, "visibility");
        maps->n_lights = scene->n_lights;
        for (size_t l = 0; l < scene->n_lights; l++) {
            stats->photons_shadow += gs.visibility[l].n_shadow;
            maps->visibility[l] = balance_trace(&gs.visibility[l], &balancing);
        }
        xfree(gs.visibility);
    }
    watched_progress_end(&balancing, 1);
    return failed ? too_many_photons(err) : 0;
}

/* The caustic map, "emitting photons towards the specular objects in the scene and
 * storing these as they hit diffuse surfaces"; not built when nothing is specular. */
static int build_caustic_map(const struct scene *scene, const struct render_settings *rs,
                             const struct jensen1996_settings *settings,
                             struct photon_maps *maps, struct jensen1996_stats *stats,
                             struct error *err)
{
    if (settings->one_map || settings->caustic_photons == 0 || scene->n_materials == 0)
        return 0;
    struct bounding_sphere *spheres = xmalloc(scene->n_materials, sizeof *spheres, "targets");
    struct emission_targets targets = {spheres, specular_targets(scene, spheres)};
    int status = 0;
    if (targets.n_spheres > 0) {
        struct trace_settings ts =
            photon_pass(rs, 1, settings->caustic_photons, PHOTON_MAP_CAUSTIC);
        ts.targets = &targets;
        struct trace_progress tp;
        trace_progress_begin(&tp, rs->progress, "caustic photon map", &ts);
        struct photon_trace traced;
        status = trace_photons(scene, &ts, &traced, err);
        trace_progress_end(&tp, status == 0);
        if (status == 0) {
            stats->photon_rays += traced.rays;
            stats->photons_emitted += traced.n_emitted;
            struct watched_progress balancing;
            watched_progress_begin(&balancing, rs->progress, "caustic photon map balancing",
                                   KDTREE_BALANCE_STEPS(traced.n_photons), "steps");
            maps->caustic = balance_trace(&traced, &balancing);
            watched_progress_end(&balancing, 1);
            stats->photons_caustic = maps->caustic->n_photons;
        }
    }
    xfree(spheres);
    return status;
}

static void photon_maps_free(struct photon_maps *maps)
{
    kdtree_free(maps->global);
    kdtree_free(maps->records);
    kdtree_free(maps->caustic);
    for (size_t l = 0; maps->visibility != NULL && l < maps->n_lights; l++)
        kdtree_free(maps->visibility[l]);
    xfree(maps->visibility);
}

int build_photon_maps(const struct scene *scene, const struct render_settings *rs,
                      const struct jensen1996_settings *settings,
                      struct jensen1996_stats *stats, struct error *err)
{
    struct photon_maps maps = {NULL, NULL, NULL, 0, NULL};
    if (build_global_map(scene, rs, settings, &maps, stats, err) < 0 ||
        build_caustic_map(scene, rs, settings, &maps, stats, err) < 0) {
        photon_maps_free(&maps);
        return -1;
    }
    global_work_add_maps(settings->work, 2 + maps.n_lights + (maps.records != NULL));
    settings->work->maps[0] = maps.global;
    settings->work->maps[1] = maps.caustic;
    for (size_t l = 0; l < maps.n_lights; l++)
        settings->work->maps[2 + l] = maps.visibility[l];
    if (maps.records != NULL)
        settings->work->maps[2 + maps.n_lights] = maps.records;
    xfree(maps.visibility);
    return 0;
}

int borrow_photon_maps(const struct scene *scene, const struct jensen1996_settings *settings,
                       struct photon_maps *maps, struct jensen1996_stats *stats,
                       struct error *err)
{
    const struct global_work *work = settings->work;
    size_t n_lights = settings->shadow_rays ? 0 : scene->n_lights;
    size_t n_records = settings->precomputed_irradiance > 0;
    int fits = work->n_maps == 2 + n_lights + n_records && work->maps[0] != NULL &&
               !(settings->one_map && work->maps[1] != NULL) && work->illumination == NULL;
    for (size_t l = 0; fits && l < n_lights + n_records; l++)
        fits = work->maps[2 + l] != NULL;
    if (!fits)
        return error_set(err, "", 0, "--load-photons: the file's photon maps are not the "
                                     "ones mode 1996 makes for this scene and these options");
    maps->global = work->maps[0];
    maps->caustic = work->maps[1];
    maps->visibility = n_lights > 0 ? work->maps + 2 : NULL;
    maps->n_lights = n_lights;
    maps->records = n_records > 0 ? work->maps[2 + n_lights] : NULL;
    stats->photons_global = maps->global->n_photons;
    stats->bytes_global_map = kdtree_bytes(maps->global);
    stats->photons_caustic = maps->caustic != NULL ? maps->caustic->n_photons : 0;
    stats->bytes_caustic_map = maps->caustic != NULL ? kdtree_bytes(maps->caustic) : 0;
    for (size_t l = 0; l < n_lights; l++)
        stats->bytes_visibility_maps += kdtree_bytes(maps->visibility[l]);
    stats->precomputed_records = maps->records != NULL ? maps->records->n_photons : 0;
    stats->bytes_precomputed = maps->records != NULL ? kdtree_bytes(maps->records) : 0;
    return 0;
}

enum visibility shadow_photon_visibility(const struct kdtree *visibility,
                                         const struct surface *s, double max_r2,
                                         struct nearest *nn)
{
    locate_photons(visibility, s->p, max_r2, J96_VISIBILITY_PHOTONS, nn);
    size_t direct = 0, shadow = 0;
    for (size_t i = 0; i < nn->found; i++) {
        if (!(vec3_dot(photon_direction(nn->photon[i]), s->ng) > 0))
            continue; /* arrived at the other side of a thin wall */
        if (nn->photon[i]->flags & PHOTON_SHADOW)
            shadow++;
        else
            direct++;
    }
    if (2 * (direct + shadow) < J96_VISIBILITY_PHOTONS || (direct > 0 && shadow > 0))
        return UNDECIDED;
    return shadow == 0 ? VISIBLE : OCCLUDED;
}
