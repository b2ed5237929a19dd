/*
 * tests/literal_jensen1994.c -- Jensen and Christensen 1994, "Photon maps in bidirectional
 * Monte Carlo ray tracing of complex objects", as the paper writes it with photon maps on
 * every object (its Fig. 5), and nothing else: the program to read before
 * src/modes/jensen1994.c. It calls the shared camera, ray casting, BRDFs, lights,
 * projection maps, photon tracer, kd-tree and irradiance cache; it has none of the mode's
 * departures and none of its bookkeeping (statistics, crops, saved work, progress).
 * `photon --mode 1994 --paper` must agree with it (tests/test_literal.c).
 *
 * The algorithm:
 *   1. light path tracing (Sec. 3): light rays leave each light through its projection
 *      maps (Sec. 3.1: stratified over the directions where objects lie, raised towards
 *      specular ones); at every surface a ray hits it deposits a photon holding the point,
 *      the normal, the energy and whether it is part of a caustic (CP: only specular
 *      reflections since the light) or not (DP) (Sec. 3.3); Russian roulette absorbs it
 *      or reflects it by the BRDF. The photons go in one kd-tree.
 *   2. irradiance from the photons (Sec. 3.3): E_x = sum_{i=1..n} e_i / (pi r^2), the
 *      sphere around x grown until it holds n photons whose normal faces x's, CP photons
 *      alone for caustics, all for the rest, with differential checking;
 *   3. Monte Carlo ray tracing (Sec. 4): each pixel the mean of spp eye rays, each
 *          L_p = L_e + L_r,   L_r = L_r,d + L_r,s,   L_r,d = L_r,d,l + L_r,d,s + L_r,d,d
 *      with the BRDF split into a diffuse-like part f_r,d and a specular-like f_r,s:
 *        L_r,d,l  stratified samples of each light through f_r,d (4.0.1);
 *        L_r,d,s  f_r,d times the caustic irradiance (4.0.2);
 *        L_r,d,d  f_r,d times the irradiance of the irradiance gradient method (Ward and
 *                 Heckbert): a cache of records, each a gather over m x n strata whose
 *                 rays, after following specular surfaces, read the irradiance of all
 *                 photons where they land (4.0.3), made where no record is usable;
 *        L_r,s    recursive Monte Carlo ray tracing: one ray sampled from f_r,s.
 *      Every path counts once: eye rays, and f_r,s's rays after them, add the emission
 *      they reach; a gather's rays add none (direct light is sampled, caustics are CP's).
 *
 * Left open by the paper, and chosen as --paper chooses (jensen1994.c): the projection
 * maps' cells and raise (photon/projection_map.h); an area light's k x k strata, a point
 * light's one sample; Russian roulette on eye paths after ROULETTE_DEPTH bounces; a
 * record's R, Ward's harmonic mean distance held between the ray offset and the scene's
 * diagonal (record_reach_at()); the diffuse-like part reflecting albedo / pi times the
 * irradiance (Sec. 5: the paper's surfaces are "specular, rough specular and
 * lambertian"); a fixed spp, since the paper's adaptive rule (Sec. 5) is not specified;
 * the sky (none in the paper) a light like the others (scene/light.h).
 *
 * Where the mode differs without a switch, so that the two agree statistically, not bit
 * for bit: records are made here as the pixels render, wherever none is usable at a
 * (Ward's way); the mode makes them in a pre-pass through pixel centres (at a / 2) and,
 * where none is usable in its final pass, gathers a share of a record's rays on the spot
 * (src/modes/README.md, "A pre-pass fills the cache"), so records lie elsewhere, and a
 * camera sample's later random numbers differ once a gather took some. Here CP photons
 * are told by their bit in the one map; the mode keeps copies in a tree of their own,
 * which gives the same estimate. A point light seen through a glossy lobe, which the
 * paper (no point lights, Sec. 5) never meets, is lost here as its ray tracing would lose
 * it; the mode samples it. Everything else draws the mode's random numbers in the mode's
 * order: the same light rays, camera points and light samples.
 */
#include "literal_jensen1994.h"

#include <math.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/modes/cache_pass.h"
#include "../src/modes/gather_plan.h"
#include "../src/modes/render.h"
#include "../src/modes/surface.h"
#include "../src/photon/estimate.h"
#include "../src/photon/projection_map.h"
#include "../src/photon/trace.h"

/* ---- 1. light path tracing ---- */

/* Sec. 3.3: "with every photon we store the intersection point, the normal, the energy
 * and a bit saying whether this photon is part of a caustic": the record's direction
 * bytes hold the normal (photon_normal()), its flags the CP bit. */
static int deposit(void *context, const struct photon_event *e)
{
    struct photon_event stored = *e;
    stored.wi = e->normal;
    return photon_trace_store(context, MAX_PHOTONS, &stored);
}

/* The photon map of `photons` light rays from the lights, through projection maps; NULL
 * when more than MAX_PHOTONS would be stored. */
static struct kdtree *light_path_tracing(const struct scene *scene, uint64_t seed,
                                         size_t photons)
{
    struct projection_settings ps = {PROJECTION_N_THETA_DEFAULT, PROJECTION_N_PHI_DEFAULT,
                                     PROJECTION_BOOST_DEFAULT};
    struct projection_maps *maps = projection_maps_build(scene, &ps);
    struct trace_settings ts;
    memset(&ts, 0, sizeof ts);
    ts.seed = seed;
    ts.n_emit = photons;
    ts.max_stored = MAX_PHOTONS;
    ts.store = PHOTON_MAP_GLOBAL; /* every deposit */
    ts.max_depth = MAX_DEPTH_LIMIT;
    ts.projection = maps;
    ts.by_parts = 1; /* a bounce leaves through f_r,d or f_r,s; CP: f_r,s's alone */
    struct photon_trace traced;
    memset(&traced, 0, sizeof traced);
    struct photon_sink sink = {deposit, &traced};
    unsigned long long rays = 0;
    int status = trace_photons_into(scene, &ts, &sink, &rays);
    projection_maps_free(maps);
    if (status < 0) {
        photon_trace_free(&traced);
        return NULL;
    }
    return balance_kdtree(traced.photons, traced.n_photons); /* the map owns them now */
}

/* ---- 3. Monte Carlo ray tracing ---- */

struct pass2 {
    const struct scene *scene;
    const struct literal_jensen1994_settings *ls;
    const struct kdtree *map;
    struct nearest *nn;                /* scratch of a photon search                     */
    struct irradiance_cache *cache;    /* the irradiance gradient method's records       */
    int strata_theta, strata_phi;      /* a record's m x n strata, one ray each          */
    struct stratum_sample *strata;     /* scratch of a gather                            */
    int light_strata;                  /* an area light's k x k samples                  */
};

/* A path from the eye (evaluated in full, adding emission) or from a gather. */
struct path {
    struct vec3 beta; /* throughput since the eye or the gathering point */
    int depth;        /* bounces so far                                  */
    int from_eye;     /* 1: adds emission and gathers; 0: a gather's, reads the map */
};

static struct vec3 radiance(const struct pass2 *p2, struct ray ray, struct path path,
                            struct rng *rng);
static struct vec3 surface_radiance(const struct pass2 *p2, const struct surface *s,
                                    struct path path, struct rng *rng);

/* L_r,d,l (4.0.1): each light sampled on a k x k grid of jittered strata through f_r,d,
 * a shadow ray each. */
static struct vec3 direct_light(const struct pass2 *p2, const struct surface *s,
                                const struct material *diffuse,
                                const struct shading_frame *frame, struct rng *rng)
{
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < p2->scene->n_lights; i++) {
        const struct light *light = &p2->scene->lights[i];
        int k = light->kind == LIGHT_POINT ? 1 : p2->light_strata, n = k * k;
        for (int j = 0; j < n; j++) {
            double u1 = (j % k + rng_uniform(rng)) / k, u2 = (j / k + rng_uniform(rng)) / k;
            struct light_sample ls;
            struct vec3 contribution;
            if (light_contribution(light, s, diffuse, frame, u1, u2, &ls, &contribution) &&
                !light_blocked(p2->scene, s, &ls))
                sum = vec3_add(sum, vec3_scale(contribution, 1.0 / n));
        }
    }
    return sum;
}

/* E at s from the photon map (step 2): CP photons alone for kinds PHOTON_CAUSTIC, all for
 * 0. */
static struct vec3 photon_irradiance(const struct pass2 *p2, const struct surface *s,
                                     unsigned kinds)
{
    struct irradiance_settings is = {p2->ls->gather, HUGE_VAL, kinds, DIFFERENTIAL_RUN, 0};
    return irradiance_estimate(p2->map, s->p, s->ng, &is, p2->nn);
}

/* L_r,s: one ray sampled from f_r,s, Russian roulette on its throughput after
 * ROULETTE_DEPTH bounces, the path going on as it came (from the eye or a gather). */
static struct vec3 specular_reflection(const struct pass2 *p2, const struct surface *s,
                                       const struct material *specular,
                                       const struct shading_frame *frame, struct path path,
                                       struct rng *rng)
{
    double u[3];
    struct brdf_sample bs;
    if (path.depth >= MAX_DEPTH_LIMIT)
        return vec3_zero();
    rng_uniforms(rng, u, 3);
    if (!brdf_sample(specular, frame, s->wo, u, &bs))
        return vec3_zero();
    double q = roulette_odds(vec3_mul(path.beta, bs.weight), path.depth);
    if (q < 1 && !(rng_uniform(rng) < q))
        return vec3_zero();
    struct vec3 weight = vec3_scale(bs.weight, 1.0 / q);
    path.beta = vec3_mul(path.beta, weight);
    path.depth++;
    return vec3_mul(weight, radiance(p2, surface_ray(s, bs.wi, bs.transmitted), path, rng));
}

/* Ward and Heckbert's gather at s, one cosine-distributed ray a stratum, each reading
 * what a gather's path finds (4.0.3), into a record. */
static struct irradiance_record gather_record(const struct pass2 *p2, const struct surface *s,
                                              const struct shading_frame *frame, int depth,
                                              struct rng *rng)
{
    int m = p2->strata_theta, n = p2->strata_phi;
    for (int j = 0; j < m; j++)
        for (int k = 0; k < n; k++) {
            struct stratum_sample sample = {{0.0, 0.0, 0.0}, INFINITY};
            struct vec3 wi;
            struct surface at;
            struct render_counters counters = {0};
            if (gather_direction(frame, s->ng, m, n, j, k, rng, &wi) &&
                ray_surface(p2->scene, surface_ray(s, wi, 0), &counters, &at,
                            &sample.distance)) {
                struct path gather = {{1.0, 1.0, 1.0}, depth + 1, 0};
                sample.radiance = surface_radiance(p2, &at, gather, rng);
            }
            p2->strata[j * n + k] = sample;
        }
    struct record_reach reach = record_reach_at(&p2->scene->camera, s->p, frame->n,
                                                p2->ls->accuracy, scene_diagonal(p2->scene),
                                                0, 0);
    return irradiance_record_of(s->p, frame->t, frame->b, frame->n, m, n, p2->strata, reach);
}

/* L_r,d,d's irradiance at s by the irradiance gradient method: interpolated from the
 * records usable at s, or, where none is, a new record's. */
static struct vec3 interreflection_irradiance(const struct pass2 *p2, const struct surface *s,
                                              const struct shading_frame *frame, int depth,
                                              struct rng *rng)
{
    struct vec3 e;
    if (irradiance_cache_lookup(p2->cache, s->p, frame->n, p2->ls->accuracy, &e))
        return e;
    struct irradiance_record record = gather_record(p2, s, frame, depth, rng);
    irradiance_cache_add(p2->cache, &record);
    return record.e;
}

/* Radiance leaving s towards s->wo on path: Sec. 4's sum, term by term. */
static struct vec3 surface_radiance(const struct pass2 *p2, const struct surface *s,
                                    struct path path, struct rng *rng)
{
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct brdf_split split = brdf_split(s->material);
    struct vec3 l = path.from_eye ? surface_emission(s) : vec3_zero();
    if (split.has_diffuse && path.from_eye) {
        l = vec3_add(l, direct_light(p2, s, &split.diffuse, &frame, rng));
        l = vec3_add(l, diffuse_reflection(s, &split.diffuse, &frame,
                                           photon_irradiance(p2, s, PHOTON_CAUSTIC)));
        l = vec3_add(l, diffuse_reflection(s, &split.diffuse, &frame,
                                           interreflection_irradiance(p2, s, &frame,
                                                                      path.depth, rng)));
    } else if (split.has_diffuse) {
        l = vec3_add(l, diffuse_reflection(s, &split.diffuse, &frame,
                                           photon_irradiance(p2, s, 0)));
    }
    if (split.has_specular)
        l = vec3_add(l, specular_reflection(p2, s, &split.specular, &frame, path, rng));
    return l;
}

/* Radiance arriving along ray on path; where it leaves the scene, the sky's on a path
 * from the eye (a gather's: the sky is a light, sampled in L_r,d,l). */
static struct vec3 radiance(const struct pass2 *p2, struct ray ray, struct path path,
                            struct rng *rng)
{
    struct surface s;
    double t;
    struct render_counters counters = {0};
    if (!ray_surface(p2->scene, ray, &counters, &s, &t))
        return path.from_eye ? p2->scene->background : vec3_zero();
    return surface_radiance(p2, &s, path, rng);
}

struct image *literal_jensen1994(const struct scene *scene,
                                 const struct literal_jensen1994_settings *ls)
{
    struct kdtree *map = light_path_tracing(scene, ls->seed, ls->photons);
    if (map == NULL)
        return NULL;
    struct pass2 p2 = {scene, ls, map, nearest_create(ls->gather),
                       irradiance_cache_create(geometry_bounds(scene->geometry), ls->accuracy),
                       0, 0, NULL, (int)floor(sqrt((double)ls->light_samples))};
    ward_strata(ls->gather_rays, &p2.strata_theta, &p2.strata_phi); /* one ray each */
    p2.strata = xmalloc((size_t)p2.strata_theta * (size_t)p2.strata_phi, sizeof *p2.strata,
                        "literal strata");
    struct image *image = image_create(scene->width, scene->height);
    for (int y = 0; y < scene->height; y++)
        for (int x = 0; x < scene->width; x++) {
            struct vec3 sum = vec3_zero();
            for (int s = 0; s < ls->spp; s++) {
                struct rng rng;
                struct ray ray = camera_sample(scene, ls->seed, x, y, s, &rng);
                struct path eye = {{1.0, 1.0, 1.0}, 0, 1};
                sum = vec3_add(sum, radiance(&p2, ray, eye, &rng));
            }
            image->pixels[(size_t)y * scene->width + x] = vec3_scale(sum, 1.0 / ls->spp);
        }
    xfree(p2.strata);
    irradiance_cache_free(p2.cache);
    nearest_free(p2.nn);
    kdtree_free(map);
    return image;
}
