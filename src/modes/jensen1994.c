/*
 * modes/jensen1994.c -- `--mode 1994`: Jensen and Christensen 1994, "Photon maps in
 * bidirectional Monte Carlo ray tracing of complex objects", Sec. 2-4, in the paper's
 * order.
 *
 * Pass 1 (Sec. 3), light path tracing: light rays leave the lights through projection
 * maps (Sec. 3.1, photon/projection_map.h: stratified over the directions in which some
 * object lies, more towards specular ones, powers weighted so the expected flux is
 * exact), and "every time the ray hits an object the energy carried by the ray is
 * deposited"; Russian roulette decides whether it is absorbed or reflected
 * (photon/trace.h). Every deposit is a photon (Sec. 3.3) holding position, normal,
 * energy and a bit saying whether it is part of a caustic (CP: only specular reflections
 * since the light) or not (DP); with --irradiance-store illumination, a deposit on a
 * quad or sphere goes to its illumination maps instead (Sec. 3.2: DI, and CI sub-maps
 * where caustics land, photon/illumination_map.h).
 *
 * Pass 2 (Sec. 4), Monte Carlo ray tracing of
 *   L_p = L_e + L_r,   L_r = L_r,s + L_r,d,   L_r,d = L_r,d,l + L_r,d,s + L_r,d,d,
 * with the BRDF split into a specular-like part f_r,s (mirror, glass, glossy lobes:
 * highly directional) and a diffuse-like part f_r,d (brdf_split(), scene/brdf.h):
 *   L_r,s    recursive ray tracing of f_r,s: every lobe of a mirror or glass, one ray
 *            sampled from a glossy lobe;
 *   L_r,d,l  direct light: stratified samples of each light through f_r,d (4.0.1);
 *   L_r,d,s  caustics: f_r,d times the irradiance of the CP photons alone (4.0.2);
 *   L_r,d,d  multiple diffuse reflections: f_r,d times the irradiance of Ward's cache
 *            with gradients (Ward and Heckbert 1992), whose records gather over the
 *            hemisphere; each gather ray reads the irradiance of ALL photons where it
 *            lands instead of recursing (4.0.3: "all secondary diffuse reflections are
 *            fetched directly from the irradiance maps"), after following specular
 *            surfaces (the L_r,d,s paths with diffuse reflections after the specular
 *            one).
 * Counting every path once: the eye's rays and the rays of f_r,s add the emission they
 * reach, since direct light is sampled through f_r,d alone; gather rays add none, at
 * their first surface (direct light) or through specular ones (caustics, held by CP).
 * The sky is a light like the others (scene/light.h): sampled in L_r,d,l, its photons in
 * the map, and what a ray that leaves the scene sees counts as emission does.
 * The diffuse-like part reflects irradiance as its directional albedo over pi: exact
 * for a Lambertian part, the paper's only diffuse-like kind.
 *
 * Determinism: every random number comes from the camera sample's stream, or in the
 * cache's pre-pass from rng_stream(seed, STREAM_CACHE, pixel, 0); the pre-pass fills the
 * cache over the whole image before the final pass, which only reads it (a point no
 * record covers gathers on the spot and keeps nothing). So a crop equals the same window
 * of the whole image. The photon map, the CP tree, the illumination maps (sized by a
 * pretrace of the whole image, not the crop) and the filled cache are the global work
 * every crop repeats; --load-photons reads them from a file instead (photon/
 * global_work.h).
 */
#include "jensen1994.h"

#include <string.h>
#include <time.h>

#include "../base/alloc.h"
#include "../photon/estimate.h"
#include "../photon/illumination_map.h"
#include "../photon/projection_map.h"
#include "../photon/trace.h"
#include "cache_pass.h"
#include "photons.h"
#include "surface.h"


struct jensen1994_settings jensen1994_settings_default(void)
{
    struct jensen1994_settings js;
    js.n_photons = J94_DEFAULT_PHOTONS;
    js.gather = J94_DEFAULT_GATHER;
    js.max_radius = 0;
    js.differential_run = DIFFERENTIAL_RUN;
    js.count_rim = 0;
    js.gather_rays = J94_DEFAULT_GATHER_RAYS;
    js.cache_accuracy = J94_DEFAULT_CACHE_ACCURACY;
    js.light_samples = J94_DEFAULT_LIGHT_SAMPLES;
    js.caustic_radius_fraction = CAUSTIC_RADIUS_FRACTION;
    js.both_lobes = 1;
    js.bounded_reach = 1;
    js.gradient_limit = 1;
    js.projection_maps = 1;
    js.illumination_maps = 0;
    js.work = NULL;
    return js;
}

/* ---- Sec. 3, pass 1: light path tracing into the photon map ---- */

/* Where pass 1 deposits: the illumination maps for photons on a surface that has one,
 * the photon map for the rest. */
struct deposits {
    struct photon_trace photons;
    struct illumination_maps *illumination; /* borrowed; NULL: photon maps everywhere */
};

/* Sec. 3.3: "with every photon we store the intersection point, the normal, the energy
 * and a bit saying whether it is a caustic photon". The 20-byte record (photon.h) keeps
 * the normal where 1996 keeps the direction, and the caustic bit among its flags. Sec.
 * 3.2: on a surface with an illumination map, the energy goes to the map instead. */
static int deposit_photon(void *context, const struct photon_event *e)
{
    struct deposits *d = context;
    if (d->illumination != NULL && illumination_covers(d->illumination, e->prim)) {
        illumination_deposit(d->illumination, e->prim, e->u, e->v, e->power,
                             e->kind == PHOTON_CAUSTIC);
        return 0;
    }
    struct photon_event stored = *e;
    stored.wi = e->normal;
    return photon_trace_store(&d->photons, MAX_PHOTONS, &stored);
}

/* Light rays through projection maps (when on) into d; fills the projection stats. */
static int trace_light_paths(const struct scene *scene, const struct trace_settings *base,
                             const struct jensen1994_settings *js, struct deposits *d,
                             struct jensen1994_stats *stats)
{
    struct trace_settings ts = *base;
    struct projection_settings ps = {PROJECTION_N_THETA_DEFAULT, PROJECTION_N_PHI_DEFAULT,
                                     PROJECTION_BOOST_DEFAULT};
    struct projection_maps *maps = js->projection_maps ? projection_maps_build(scene, &ps) : NULL;
    ts.projection = maps;
    struct photon_sink sink = {deposit_photon, d};
    int status = trace_photons_into(scene, &ts, &sink, &stats->photon_rays);
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
        receives[i] = (unsigned char)brdf_has_diffuse(&scene->materials[material]);
    }
    return receives;
}

/* A kd-tree of copies of the CP photons among traced's (departs from Sec. 3.3, which
 * keeps one map and tells CP photons by their bit: searched for CP photons alone, that
 * map must visit every photon within the radius wherever caustics are sparse or absent,
 * which made the Cornell box's final pass grow with the photons, 85 s at 200,000 and
 * 190 s at 500,000. The copies cost 20 bytes per CP photon.) */
static struct kdtree *caustic_photons_of(const struct photon_trace *traced)
{
    struct photon *cp = xmalloc(traced->n_caustic > 0 ? traced->n_caustic : 1, sizeof *cp,
                                "caustic photons");
    size_t n = 0;
    for (size_t i = 0; i < traced->n_photons; i++)
        if (traced->photons[i].flags & PHOTON_CAUSTIC)
            cp[n++] = traced->photons[i];
    return balance_kdtree(cp, n); /* takes them */
}

/* The illumination maps' figures for --stats. */
static void count_illumination(const struct illumination_maps *maps,
                               struct jensen1994_stats *stats)
{
    struct illumination_stats st = illumination_maps_stats(maps);
    stats->illumination_maps = st.n_maps;
    stats->illumination_di_elements = st.di_elements;
    stats->illumination_ci_maps = st.ci_maps;
    stats->bytes_illumination_maps = st.bytes;
}

int jensen1994_trace(const struct scene *scene, uint64_t seed, int max_depth,
                     const struct jensen1994_settings *js, struct irradiance_stores *out,
                     struct jensen1994_stats *stats, struct error *err)
{
    struct trace_settings ts;
    memset(&ts, 0, sizeof ts);
    ts.seed = seed;
    ts.n_emit = js->n_photons;
    ts.max_stored = MAX_PHOTONS;
    ts.store = PHOTON_MAP_GLOBAL; /* every deposit: direct, caustic and indirect */
    ts.max_depth = max_depth;
    ts.targets = NULL;
    ts.projection = NULL;
    struct deposits d;
    memset(&d, 0, sizeof d);
    d.photons.photons = NULL;
    d.illumination = NULL;
    if (js->illumination_maps) {
        double *footprint = pretrace_footprints(scene);
        unsigned char *receives = receiving_primitives(scene);
        d.illumination = illumination_maps_create(scene->geometry, scene_diagonal(scene),
                                                  footprint, receives);
        xfree(receives);
        xfree(footprint);
    }
    if (trace_light_paths(scene, &ts, js, &d, stats) < 0) {
        photon_trace_free(&d.photons);
        illumination_maps_free(d.illumination);
        return error_set(err, "", 0,
                         "photon map: more than %d photons would be stored; emit fewer "
                         "photons or follow fewer bounces (--max-depth)", MAX_PHOTONS);
    }
    stats->photons_emitted = ts.n_emit;
    stats->photons_caustic = d.photons.n_caustic;
    out->caustics = caustic_photons_of(&d.photons);
    out->photons = balance_kdtree(d.photons.photons, d.photons.n_photons); /* takes them */
    stats->photons_stored = out->photons->n_photons;
    stats->bytes_photon_map = kdtree_bytes(out->photons);
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
    illumination_maps_free(stores->illumination);
    stores->photons = NULL;
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
    return irradiance_estimate(stores->photons, q->x, q->n, q->estimate, nn);
}

/* ---- Sec. 4, pass 2: Monte Carlo ray tracing ---- */

/* A path from the eye, or from a gather (whose surfaces read the irradiance stores). */
struct path {
    struct vec3 beta; /* throughput since the eye or the gathering point                */
    int depth;        /* bounces so far                                                  */
    int secondary;    /* 1 on a gather ray: read the photon map, add no emission         */
};

struct j94 {
    const struct scene *scene;
    const struct jensen1994_settings *js;
    struct irradiance_stores stores;
    struct irradiance_settings all_photons, caustic_photons;
    struct irradiance_cache *cache;
    int filling_cache;               /* the pre-pass: records where none is usable      */
    int strata_theta, strata_phi;    /* a record's m x n strata, one ray each            */
    int light_strata;                /* each light sampled on light_strata^2 strata      */
    double diagonal;                 /* of the scene's box                               */
    int max_depth;                   /* longest chain of bounces followed                */
    struct nearest *nn;              /* scratch for every photon search                  */
    struct stratum_sample *strata;   /* scratch of a gather                              */
    struct jensen1994_stats *stats;
};

static struct vec3 trace(const struct j94 *m, struct ray ray, struct path path, struct rng *rng,
                         struct render_counters *counters);
static struct vec3 trace_from(const struct j94 *m, const struct surface *s, struct path path,
                              struct rng *rng, struct render_counters *counters);

/* Radiance that the diffuse-like part reflects from irradiance e: albedo / pi times e. */
static struct vec3 diffuse_reflection(const struct surface *s, const struct material *diffuse,
                                      const struct shading_frame *frame, struct vec3 e)
{
    return vec3_mul(brdf_albedo(diffuse, frame, s->wo), vec3_scale(e, 1.0 / PI));
}

/* -- 4.0.1 L_r,d,l: direct light -- */

/* Each light sampled on a k x k grid of jittered strata of its sample space, through the
 * diffuse-like part, with a shadow ray per sample; a point light, whose every sample is
 * the same, once. */
static struct vec3 direct_light(const struct j94 *m, const struct surface *s,
                                const struct material *diffuse,
                                const struct shading_frame *frame, struct rng *rng,
                                struct render_counters *counters)
{
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < m->scene->n_lights; i++) {
        int k = m->scene->lights[i].kind == LIGHT_POINT ? 1 : m->light_strata;
        for (int j = 0; j < k * k; j++) {
            double u1 = (j % k + rng_uniform(rng)) / k, u2 = (j / k + rng_uniform(rng)) / k;
            struct light_sample ls;
            struct vec3 contribution;
            if (!light_contribution(&m->scene->lights[i], s, diffuse, frame, u1, u2, &ls,
                                    &contribution))
                continue;
            m->stats->shadow_rays++;
            counters->rays++;
            if (!light_blocked(m->scene, s, &ls))
                sum = vec3_add(sum, vec3_scale(contribution, 1.0 / (k * k)));
        }
    }
    return sum;
}

/* -- 4.0.2 L_r,d,s: caustics, from the CP photons alone -- */

static struct vec3 caustic_light(const struct j94 *m, const struct surface *s,
                                 const struct material *diffuse,
                                 const struct shading_frame *frame)
{
    struct store_query q = {s->p, s->ng, s->prim, s->u, s->v, &m->caustic_photons};
    return diffuse_reflection(s, diffuse, frame, stored_irradiance(&m->stores, &q, m->nn));
}

/* -- L_r,s: the specular-like part by recursive Monte Carlo ray tracing -- */

/* The radiance arriving along lobe bs of f_r,s times its weight, with Russian roulette
 * after ROULETTE_DEPTH bounces. */
static struct vec3 follow_lobe(const struct j94 *m, const struct surface *s,
                               const struct brdf_sample *bs, struct path path, struct rng *rng,
                               struct render_counters *counters)
{
    path.beta = vec3_mul(path.beta, bs->weight);
    double q = roulette_odds(path.beta, path.depth);
    if (q < 1 && !(rng_uniform(rng) < q))
        return vec3_zero(); /* absorbed (always when q = 0) */
    path.beta = vec3_scale(path.beta, 1.0 / q);
    path.depth++;
    struct vec3 li = trace(m, surface_ray(s, bs->wi, bs->transmitted), path, rng, counters);
    return vec3_mul(vec3_scale(bs->weight, 1.0 / q), li);
}

/* Recursive ray tracing of f_r,s: an ideal mirror's or glass's every lobe (reflection and
 * refraction both, as Whitted's ray tracer, so glass shows no noise from choosing
 * between them; with both_lobes off, the paper's Monte Carlo: one lobe, chosen by the
 * BRDF's sampling), else one direction sampled from the glossy lobe. */
static struct vec3 specular_light(const struct j94 *m, const struct surface *s,
                                  const struct material *specular,
                                  const struct shading_frame *frame, struct path path,
                                  struct rng *rng, struct render_counters *counters)
{
    if (path.depth >= m->max_depth)
        return vec3_zero();
    struct vec3 sum = vec3_zero();
    if (m->js->both_lobes && brdf_is_delta(specular)) {
        struct brdf_sample lobes[2];
        int n_lobes = brdf_delta_lobes(specular, frame, s->wo, lobes);
        for (int k = 0; k < n_lobes; k++)
            sum = vec3_add(sum, follow_lobe(m, s, &lobes[k], path, rng, counters));
        return sum;
    }
    double u[3];
    for (int k = 0; k < 3; k++)
        u[k] = rng_uniform(rng); /* one by one: an initializer list's order is unspecified */
    struct brdf_sample bs;
    if (brdf_sample(specular, frame, s->wo, u, &bs))
        sum = follow_lobe(m, s, &bs, path, rng, counters);
    return sum;
}

/* -- 4.0.3 L_r,d,d: multiple diffuse reflections by irradiance gradients -- */

/* Ward and Heckbert's gather at s: one cosine-distributed ray per stratum, each bringing
 * the radiance a secondary path finds (the irradiance stores where it lands). Fills
 * m->strata; returns the record with its radius bounded as cache_pass.h says. */
static struct irradiance_record gather_record(const struct j94 *m, const struct surface *s,
                                              const struct shading_frame *frame,
                                              struct path path, struct rng *rng,
                                              struct render_counters *counters)
{
    struct path gather = {vec3(1, 1, 1), path.depth + 1, 1};
    for (int j = 0; j < m->strata_theta; j++) {
        for (int k = 0; k < m->strata_phi; k++) {
            double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
            struct vec3 local = stratum_direction(m->strata_theta, m->strata_phi, j, k, u1, u2);
            struct vec3 wi = vec3_add(vec3_add(vec3_scale(frame->t, local.x),
                                               vec3_scale(frame->b, local.y)),
                                      vec3_scale(frame->n, local.z));
            struct stratum_sample *sample = &m->strata[j * m->strata_phi + k];
            sample->radiance = vec3_zero();
            sample->distance = INFINITY;
            if (!(vec3_dot(wi, s->ng) > 0))
                continue; /* below the geometric surface: no light arrives */
            struct surface at;
            double t;
            m->stats->gradient_rays++;
            if (!ray_surface(m->scene, surface_ray(s, wi, 0), counters, &at, &t))
                continue; /* the sky: direct light, which direct_light() samples */
            sample->radiance = trace_from(m, &at, gather, rng, counters);
            sample->distance = t;
        }
    }
    struct record_reach reach =
        record_reach_at(&m->scene->camera, s->p, frame->n, m->js->cache_accuracy, m->diagonal,
                        m->js->bounded_reach, m->js->gradient_limit);
    return irradiance_record_of(s->p, frame->t, frame->b, frame->n, m->strata_theta,
                                m->strata_phi, m->strata, reach);
}

/* The irradiance of multiple diffuse reflections at s: interpolated from the cache where
 * a record is usable (Ward 1988); else gathered, and in the pre-pass kept as a record. */
static struct vec3 diffuse_interreflection(const struct j94 *m, const struct surface *s,
                                           const struct shading_frame *frame, struct path path,
                                           struct rng *rng, struct render_counters *counters)
{
    struct vec3 e;
    double a = m->js->cache_accuracy * (m->filling_cache ? CACHE_FILL_STRICTNESS : 1.0);
    if (irradiance_cache_lookup(m->cache, s->p, frame->n, a, &e))
        return e;
    struct irradiance_record record = gather_record(m, s, frame, path, rng, counters);
    if (m->filling_cache)
        irradiance_cache_add(m->cache, &record);
    else
        m->stats->gather_fallbacks++;
    return record.e;
}

/* -- a surface, term by term -- */

/* Radiance leaving s towards s->wo on a path from the eye: L_e + L_r,s + L_r,d. */
static struct vec3 eye_radiance(const struct j94 *m, const struct surface *s, struct path path,
                                struct rng *rng, struct render_counters *counters)
{
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct brdf_split split = brdf_split(s->material);
    struct vec3 l = surface_emission(s);
    if (split.has_diffuse) {
        l = vec3_add(l, direct_light(m, s, &split.diffuse, &frame, rng, counters));
        l = vec3_add(l, caustic_light(m, s, &split.diffuse, &frame));
        struct vec3 e = diffuse_interreflection(m, s, &frame, path, rng, counters);
        l = vec3_add(l, diffuse_reflection(s, &split.diffuse, &frame, e));
    }
    if (split.has_specular)
        l = vec3_add(l, specular_light(m, s, &split.specular, &frame, path, rng, counters));
    return l;
}

/* Radiance leaving s towards s->wo on a gather ray (Sec. 4.0.3): the diffuse-like part
 * reflects the irradiance of all photons, read from the photon map; the specular-like
 * part is followed on; no emission. */
static struct vec3 secondary_radiance(const struct j94 *m, const struct surface *s,
                                      struct path path, struct rng *rng,
                                      struct render_counters *counters)
{
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct brdf_split split = brdf_split(s->material);
    struct vec3 l = vec3_zero();
    if (split.has_diffuse) {
        struct store_query q = {s->p, s->ng, s->prim, s->u, s->v, &m->all_photons};
        l = diffuse_reflection(s, &split.diffuse, &frame, stored_irradiance(&m->stores, &q, m->nn));
    }
    if (split.has_specular)
        l = vec3_add(l, specular_light(m, s, &split.specular, &frame, path, rng, counters));
    return l;
}

static struct vec3 trace_from(const struct j94 *m, const struct surface *s, struct path path,
                              struct rng *rng, struct render_counters *counters)
{
    return path.secondary ? secondary_radiance(m, s, path, rng, counters)
                          : eye_radiance(m, s, path, rng, counters);
}

static struct vec3 trace(const struct j94 *m, struct ray ray, struct path path, struct rng *rng,
                         struct render_counters *counters)
{
    struct surface s;
    double t;
    if (!ray_surface(m->scene, ray, counters, &s, &t)) /* the sky, emission as any other */
        return path.secondary ? vec3_zero() : m->scene->background;
    return trace_from(m, &s, path, rng, counters);
}

static struct vec3 j94_radiance(const void *mode, struct ray ray, struct rng *rng,
                                struct render_counters *counters)
{
    struct path eye = {vec3(1, 1, 1), 0, 0};
    return trace(mode, ray, eye, rng, counters);
}

/* ---- putting it together ---- */

/* The mode's state from the scene and the settings: estimates, strata, cache, scratch. */
static void set_up(struct j94 *m, const struct scene *scene, const struct render_settings *rs,
                   const struct jensen1994_settings *js)
{
    struct aabb box = geometry_bounds(scene->geometry);
    m->scene = scene;
    m->js = js;
    m->max_depth = rs->max_depth;
    m->diagonal = scene_diagonal(scene);
    double max_radius = js->max_radius > 0 ? js->max_radius
                                           : PHOTONS_RADIUS_FRACTION * m->diagonal;
    struct irradiance_settings all = {js->gather, max_radius * max_radius, 0,
                                      js->differential_run, js->count_rim};
    m->all_photons = all;
    m->caustic_photons = all;
    m->caustic_photons.max_r2 *= js->caustic_radius_fraction * js->caustic_radius_fraction;
    m->caustic_photons.kinds = PHOTON_CAUSTIC;
    /* Ward and Heckbert's strata, m x n with n about pi m, one ray each */
    m->strata_theta = (int)floor(sqrt(js->gather_rays / PI) + 0.5);
    m->strata_theta = m->strata_theta < 1 ? 1 : m->strata_theta;
    m->strata_phi = js->gather_rays / m->strata_theta;
    m->light_strata = (int)floor(sqrt((double)js->light_samples));
    m->filling_cache = 0;
    m->cache = irradiance_cache_create(isfinite(box.lo.x) ? box : (struct aabb){vec3_zero(),
                                                                               vec3_zero()},
                                       js->cache_accuracy);
    m->nn = nearest_create(js->gather);
    m->strata = xmalloc((size_t)m->strata_theta * (size_t)m->strata_phi, sizeof *m->strata,
                        "strata");
}

static void tear_down(struct j94 *m)
{
    xfree(m->strata);
    nearest_free(m->nn);
    irradiance_cache_free(m->cache); /* m->stores are the work's */
}

/* Pass 1 into work when it is empty (maps[0] the photon map, maps[1] the CP photons'
 * tree, and the illumination maps when js asks for them), else the stores work holds
 * (loaded from a file). m->stores borrows them from work. */
static int photon_stores(struct j94 *m, const struct scene *scene,
                         const struct render_settings *rs, struct global_work *work,
                         struct error *err)
{
    if (work->n_maps == 0) {
        if (jensen1994_trace(scene, rs->seed, rs->max_depth, m->js, &m->stores, m->stats,
                             err) < 0)
            return -1;
        global_work_add_maps(work, 2);
        work->maps[0] = m->stores.photons;
        work->maps[1] = m->stores.caustics;
        work->illumination = m->stores.illumination;
        return 0;
    }
    if (work->n_maps != 2 || work->maps[0] == NULL || work->maps[1] == NULL ||
        (work->illumination != NULL) != (m->js->illumination_maps != 0))
        return error_set(err, "", 0, "--load-photons: the file does not hold the two photon "
                                     "maps (and, with --irradiance-store illumination, the "
                                     "illumination maps) mode 1994 saves");
    m->stores.photons = work->maps[0];
    m->stores.caustics = work->maps[1];
    m->stores.illumination = work->illumination;
    if (work->illumination != NULL)
        count_illumination(work->illumination, m->stats);
    m->stats->photons_stored = work->maps[0]->n_photons;
    m->stats->photons_caustic = work->maps[1]->n_photons;
    m->stats->bytes_photon_map = kdtree_bytes(work->maps[0]);
    m->stats->bytes_caustic_photons = kdtree_bytes(work->maps[1]);
    return 0;
}

struct render_result render_jensen1994(const struct scene *scene,
                                       const struct render_settings *rs,
                                       const struct jensen1994_settings *js, int want_variance,
                                       struct render_counters *counters,
                                       struct jensen1994_stats *stats, struct error *err)
{
    struct render_result result = {NULL, NULL, 0.0};
    memset(stats, 0, sizeof *stats);
    struct j94 m;
    memset(&m, 0, sizeof m);
    m.stats = stats;
    m.js = js;
    struct global_work own_work = {NULL, 0, NULL, 0, NULL}; /* without js->work: made, freed */
    struct global_work *work = js->work != NULL ? js->work : &own_work;
    int loaded = work->n_maps > 0;
    clock_t start = clock();
    if (photon_stores(&m, scene, rs, work, err) < 0) {
        global_work_free(&own_work);
        return result;
    }
    stats->seconds_photons = cpu_seconds(start);
    set_up(&m, scene, rs, js);
    stats->strata_theta = m.strata_theta;
    stats->strata_phi = m.strata_phi;
    start = clock();
    struct radiance_estimator estimator = {j94_radiance, &m};
    if (loaded) {
        global_work_fill_cache(work, m.cache);
    } else {
        m.filling_cache = 1;
        fill_cache_pass(scene, rs->seed, estimator, m.cache, rs->progress, counters);
        m.filling_cache = 0;
        global_work_keep_cache(work, m.cache);
    }
    stats->seconds_cache = cpu_seconds(start);
    stats->cache_records = irradiance_cache_records(m.cache);
    stats->bytes_cache = irradiance_cache_bytes(m.cache);
    result = render_pixels(scene, rs, estimator, want_variance, NULL, counters);
    stats->seconds_final_pass = result.seconds;
    result.seconds += stats->seconds_photons + stats->seconds_cache;
    tear_down(&m);
    global_work_free(&own_work);
    return result;
}
