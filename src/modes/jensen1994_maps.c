/*
 * modes/jensen1994_maps.c -- pass 1 of `--mode 1994` (jensen1994_maps.h): light rays from
 * the lights through projection maps, deposited into the photon map or the illumination
 * maps (Jensen and Christensen 1994, Sec. 3-3.3), and the irradiance read back from them.
 */
#include "jensen1994_maps.h"

#include <string.h>

#include "../base/alloc.h"
#include "../photon/estimate.h"
#include "../photon/illumination_map.h"
#include "../photon/kdtree.h"
#include "../photon/precomputed_irradiance.h"
#include "../photon/projection_map.h"
#include "../photon/trace.h"
#include "../scene/brdf.h"
#include "trace_progress.h"

/* ---- Sec. 3, pass 1: light path tracing into the photon map ---- */

/* Where pass 1 deposits: the illumination maps for photons on a surface that has one,
 * the photon map for the rest. */
struct deposits {
    struct photon_trace photons;
    struct photon_trace glossy;                 /* those that keeps_direction()        */
    struct illumination_maps *illumination;     /* borrowed; NULL: photon maps everywhere */
    const struct scene *scene;                  /* borrowed                            */
};

int keeps_direction(const struct illumination_maps *illumination, const struct material *m,
                    int prim)
{
    if (illumination != NULL && illumination_covers(illumination, prim))
        return 0;
    struct brdf_split split = brdf_split(m);
    return split.has_diffuse && !split.lambertian;
}

/* Sec. 3.3: "with every photon we store the intersection point, the normal, the energy
 * and a bit saying whether it is a caustic photon". The 20-byte record (photon.h) keeps
 * the normal where 1996 keeps the direction, and the caustic bit among its flags. Sec.
 * 3.2: on a surface with an illumination map, the energy goes to the map instead. A
 * photon on a diffuse-like part that is not Lambertian keeps its direction instead, in a
 * tree of its own (keeps_direction()). The two trees hold MAX_PHOTONS between them. */
static int deposit_photon(void *context, const struct photon_event *e)
{
    struct deposits *d = context;
    if (d->illumination != NULL && illumination_covers(d->illumination, e->prim)) {
        illumination_deposit(d->illumination, e->prim, e->u, e->v, e->power,
                             e->kind == PHOTON_CAUSTIC);
        return 0;
    }
    const struct material *m =
        &d->scene->materials[geometry_primitive_material(d->scene->geometry, e->prim)];
    size_t room = MAX_PHOTONS - d->photons.n_photons - d->glossy.n_photons;
    if (keeps_direction(d->illumination, m, e->prim))
        return photon_trace_store(&d->glossy, d->glossy.n_photons + room, e);
    struct photon_event stored = *e;
    stored.wi = e->normal;
    return photon_trace_store(&d->photons, d->photons.n_photons + room, &stored);
}

/* Light rays through projection maps (when on) into d; fills the projection stats. */
static int trace_light_paths(const struct scene *scene, const struct trace_settings *base,
                             const struct jensen1994_settings *settings, struct deposits *d,
                             struct jensen1994_stats *stats, int progress)
{
    struct trace_settings ts = *base;
    struct projection_settings ps = {PROJECTION_N_THETA_DEFAULT, PROJECTION_N_PHI_DEFAULT,
                                     PROJECTION_BOOST_DEFAULT};
    struct projection_maps *maps =
        settings->projection_maps ? projection_maps_build(scene, &ps) : NULL;
    ts.projection = maps;
    struct photon_sink sink = {deposit_photon, d};
    struct trace_progress tp;
    trace_progress_begin(&tp, progress, "photon tracing", &ts);
    int status = trace_photons_into(scene, &ts, &sink, &stats->photon_rays);
    trace_progress_end(&tp, status == 0);
    if (maps != NULL) {
        struct projection_stats pst = projection_maps_stats(maps);
        stats->projection_maps = pst.n_maps;
        stats->projection_marked = pst.marked_fraction;
        stats->bytes_projection_maps = pst.bytes;
    }
    projection_maps_free(maps);
    return status;
}

/* Sec. 3.2's pretrace: "the distance between rays going through adjacent pixels and
 * striking the same object". One ray through the centre of every pixel of the whole
 * image; footprint[prim] (n_prims entries, owned by the caller) becomes the smallest
 * distance between the hits of horizontally or vertically adjacent pixels on prim, 0
 * where no two adjacent pixels hit prim. Row by row, two rows kept. */
static double *pretrace_footprints(const struct scene *scene)
{
    size_t n_prims = geometry_primitive_count(scene->geometry);
    double *footprint = xcalloc(n_prims > 0 ? n_prims : 1, sizeof *footprint, "footprints");
    size_t width = (size_t)scene->width;
    int *prim = xmalloc(2 * width, sizeof *prim, "pretrace");
    struct vec3 *p = xmalloc(2 * width, sizeof *p, "pretrace");
    for (int y = 0; y < scene->height; y++) {
        size_t row = (size_t)(y % 2) * width, above = (size_t)((y + 1) % 2) * width;
        for (size_t x = 0; x < width; x++) {
            struct hit hit;
            struct ray ray = camera_ray(&scene->camera, x + 0.5, y + 0.5);
            prim[row + x] = scene_intersect(scene, ray, INFINITY, &hit) ? hit.prim : -1;
            p[row + x] = hit.p;
            for (int k = 0; k < 2; k++) { /* the left neighbour, the one above */
                size_t other = k == 0 ? row + x - 1 : above + x;
                if ((k == 0 ? x == 0 : y == 0) || prim[row + x] < 0 ||
                    prim[other] != prim[row + x])
                    continue;
                double d = vec3_length(vec3_sub(p[row + x], p[other]));
                double *f = &footprint[prim[row + x]];
                *f = *f == 0 || d < *f ? d : *f;
            }
        }
    }
    xfree(p);
    xfree(prim);
    return footprint;
}

/* Per primitive, whether photons can be stored on it (a non-specular part): mirrors and
 * glass get no illumination map, since no photon would ever reach one. Owned by the
 * caller. */
static unsigned char *receiving_primitives(const struct scene *scene)
{
    size_t n_prims = geometry_primitive_count(scene->geometry);
    unsigned char *receives = xmalloc(n_prims > 0 ? n_prims : 1, sizeof *receives,
                                      "receiving primitives");
    for (size_t i = 0; i < n_prims; i++) {
        int material = geometry_primitive_material(scene->geometry, (int)i);
        receives[i] = (unsigned char)brdf_has_non_delta(&scene->materials[material]);
    }
    return receives;
}

/* A kd-tree of copies of the CP photons among traced's (departs from Sec. 3.3, which
 * keeps one map and tells CP photons by their bit: searched for CP photons alone, that
 * map must visit every photon within the radius wherever caustics are sparse or absent,
 * so the Cornell box's final pass would grow with the photons: src/modes/measured.md.
 * The copies cost 20 bytes per CP photon.) The next part of balancing's line. */
static struct kdtree *caustic_photons_of(const struct photon_trace *traced,
                                         struct watched_progress *balancing)
{
    struct photon *cp = xmalloc(traced->n_caustic > 0 ? traced->n_caustic : 1, sizeof *cp,
                                "caustic photons");
    size_t n = 0;
    for (size_t i = 0; i < traced->n_photons; i++)
        if (traced->photons[i].flags & PHOTON_CAUSTIC)
            cp[n++] = traced->photons[i];
    return balance_part(cp, n, balancing); /* takes them */
}

void count_illumination(const struct illumination_maps *maps,
                               struct jensen1994_stats *stats)
{
    struct illumination_stats st = illumination_maps_stats(maps);
    stats->illumination_maps = st.n_maps;
    stats->illumination_di_elements = st.di_elements;
    stats->illumination_ci_maps = st.ci_maps;
    stats->bytes_illumination_maps = st.bytes;
}

int jensen1994_trace(const struct scene *scene, uint64_t seed, int max_depth,
                     const struct jensen1994_settings *settings, struct irradiance_stores *out,
                     struct jensen1994_stats *stats, int progress, struct error *err)
{
    struct trace_settings ts;
    memset(&ts, 0, sizeof ts);
    ts.seed = seed;
    ts.n_emit = settings->n_photons;
    ts.max_stored = MAX_PHOTONS;
    ts.store = PHOTON_MAP_GLOBAL; /* every deposit: direct, caustic and indirect */
    ts.max_depth = max_depth;
    ts.targets = NULL;
    ts.projection = NULL;
    ts.by_parts = 1; /* CP: "only specular reflections", f_r,s's glossy lobes among them */
    struct deposits d;
    memset(&d, 0, sizeof d);
    d.photons.photons = NULL;
    d.glossy.photons = NULL;
    d.illumination = NULL;
    d.scene = scene;
    if (settings->illumination_maps) {
        double *footprint = pretrace_footprints(scene);
        unsigned char *receives = receiving_primitives(scene);
        d.illumination = illumination_maps_create(scene->geometry, scene_diagonal(scene),
                                                  footprint, receives);
        xfree(receives);
        xfree(footprint);
    }
    if (trace_light_paths(scene, &ts, settings, &d, stats, progress) < 0) {
        photon_trace_free(&d.photons);
        photon_trace_free(&d.glossy);
        illumination_maps_free(d.illumination);
        return error_set(err, "", 0,
                         "photon map: more than %d photons would be stored; emit fewer "
                         "photons or follow fewer bounces (--max-depth)", MAX_PHOTONS);
    }
    stats->photons_emitted = ts.n_emit;
    stats->photons_caustic = d.photons.n_caustic;
    struct watched_progress balancing; /* the three maps on one line */
    watched_progress_begin(&balancing, progress, "photon map balancing",
                           KDTREE_BALANCE_STEPS(d.photons.n_caustic + d.photons.n_photons +
                                                d.glossy.n_photons), "steps");
    out->caustics = caustic_photons_of(&d.photons, &balancing);
    /* the maps take the photons */
    out->photons = balance_part(d.photons.photons, d.photons.n_photons, &balancing);
    out->glossy = balance_part(d.glossy.photons, d.glossy.n_photons, &balancing);
    watched_progress_end(&balancing, 1);
    stats->photons_stored = out->photons->n_photons + out->glossy->n_photons;
    stats->photons_glossy = out->glossy->n_photons;
    stats->bytes_photon_map = kdtree_bytes(out->photons) + kdtree_bytes(out->glossy);
    stats->bytes_caustic_photons = kdtree_bytes(out->caustics);
    out->illumination = d.illumination;
    if (out->illumination != NULL) {
        illumination_maps_finish(out->illumination, scene->geometry);
        count_illumination(out->illumination, stats);
    }
    return 0;
}

void irradiance_stores_free(struct irradiance_stores *stores)
{
    kdtree_free(stores->photons);
    kdtree_free(stores->caustics);
    kdtree_free(stores->glossy);
    illumination_maps_free(stores->illumination);
    stores->photons = NULL;
    stores->glossy = NULL;
    stores->caustics = NULL;
    stores->illumination = NULL;
}

struct vec3 stored_irradiance(const struct irradiance_stores *stores,
                              const struct store_query *q, struct nearest *nn)
{
    if (stores->illumination != NULL && illumination_covers(stores->illumination, q->prim))
        return illumination_irradiance(stores->illumination, q->prim, q->u, q->v,
                                       q->estimate->kinds == PHOTON_CAUSTIC);
    if (q->estimate->kinds == PHOTON_CAUSTIC) /* all of them are: no filter to apply */
        return irradiance_estimate(stores->caustics, q->x, q->n, q->estimate, nn);
    struct vec3 e;
    double r2;
    if (q->precomputed != NULL && precomputed_irradiance_at(q->precomputed, q->x, q->n, nn, &e,
                                                            &r2))
        return e;
    return irradiance_estimate(stores->photons, q->x, q->n, q->estimate, nn);
}

