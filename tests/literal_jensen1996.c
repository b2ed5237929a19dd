/*
 * tests/literal_jensen1996.c -- Jensen 1996, "Global illumination using photon maps", as
 * the paper writes it, and nothing else: the program to read before src/modes/jensen1996.c.
 * It calls the shared camera, ray casting, BRDFs, lights, photon tracer, kd-tree, density
 * estimates and irradiance cache; it has none of the mode's departures (precomputed
 * irradiance, every shadow ray cast, discs over what they cover, both lobes of glass,
 * the through-gloss and corner-photon shortcuts, the rim photon left out, a maximum radius,
 * a record's bounded reach and gradient limit) and none of its bookkeeping (statistics,
 * crops, saved work, progress). `photon --mode 1996 --paper` must agree with it
 * (tests/test_literal.c).
 *
 * The algorithm:
 *   Pass 1 (Sec. 3): two photon maps, each photon stored at every surface with a diffuse
 *     part it hits, Russian roulette absorbing it or reflecting it by the BRDF:
 *       the caustic map: photons emitted towards the specular objects, stored after
 *         specular reflections only (L S+ D: f_r,s is "highly glossy and ideal specular");
 *       the global map: photons emitted towards all objects, each classified (Fig. 1) as
 *         direct (D), indirect (I), and, behind each first hit along the light ray, shadow
 *         photons (S, Jensen and Christensen 1995), which hold no light.
 *   Pass 2 (Sec. 4): each pixel the mean of spp eye rays; where a ray meets a surface,
 *          L_s = L_e + L_r,   Eq. 2: L_r = int f_r L_i,l + int f_r,s (L_i,c + L_i,d)
 *                                        + int f_r,d L_i,c + int f_r,d L_i,d,
 *     each integral evaluated accurately (a surface seen directly or via a few specular
 *     reflections, or at the end of a gather ray shorter than a small threshold: a
 *     corner) or approximately (after a diffuse reflection, or at a low weight):
 *       direct (4.1)    accurate: each light sampled through f_r, a shadow ray only where
 *                       its nearest direct and shadow photons mix or are too few;
 *       specular (4.2)  Monte Carlo ray tracing importance-sampled by f_r,s: up to
 *                       glossy_rays rays at the first accurate glossy surface, else one;
 *       caustics (4.3)  accurate: the caustic map's estimate, cone-filtered (Eq. 5);
 *       soft (4.4)      accurate: a final gather whose directions the global map's photons
 *                       and f_r,d guide (Jensen 1995), through Ward and Heckbert's
 *                       irradiance gradient cache on Lambertian surfaces;
 *       approximate     direct, caustics and soft light in one: the global map's radiance
 *                       estimate through f_r,d (Eq. 3); the specular part still traced.
 *     Every path counts once: light sampling has what a glossy lobe or a diffuse part sees
 *     of the lights, so rays sampled there add no emission at their next surface (a mirror
 *     or glass's rays do: nothing else samples that light); a gather ray takes only light
 *     reflected diffusely at least once (4.4's L_i,d): no emission through any chain of
 *     f_r,s reflections (caustics, in the caustic map), and where it ends, direct light
 *     through f_r,d alone (the light f_r,s reflects there is a caustic at the gather).
 *
 * Left open by the paper, and chosen as --paper chooses (jensen1996.c, gather_plan.h): one
 * sample of each light at an accurate point; the visibility test's 16 photons, of the
 * light's own direct and shadow photons (the paper's scenes' photons name no light), too
 * few below 8; the small threshold, accurate_distance radii of the global estimate at
 * the gather ray's end; a corner's own gather's rays approximate at any length; a low
 * weight, below accurate_weight; the importance met with the cache's strata by stratified
 * allocation (every stratum a ray, the rest by photon flux times f_r,d); a diffuse part
 * whose f_r,d is not Lambertian (no cache holds it) reflecting a full gather of f_r,d L;
 * Ward's R held between the ray offset and the scene's diagonal (record_reach_at()); eye
 * paths ended by Russian roulette after ROULETTE_DEPTH bounces; a fixed spp; the cone
 * filter's k = 1, the paper's "generally works very well"; the sky a light like the
 * others (scene/light.h).
 *
 * Where the mode differs without a switch, so that the two agree statistically, not bit
 * for bit: records are made here as the pixels render, wherever none is usable at a
 * (Ward's way); the mode makes them in a pre-pass through pixel centres (at a / 2) and,
 * where none is usable in its final pass, gathers the camera sample's share of a record's
 * rays on the spot (src/modes/README.md), so records lie elsewhere, and a camera sample's
 * later random numbers differ once a gather took some; at a diffuse part that is not
 * Lambertian the mode spreads one gather's rays over a pixel's camera samples, where this
 * program gathers in full for each. Everything else draws the mode's random numbers in
 * the mode's order: the same photons, camera points, light samples and specular rays.
 */
#include "literal_jensen1996.h"

#include <math.h>
#include <string.h>

#include "../src/base/alloc.h"
#include "../src/modes/cache_pass.h"
#include "../src/modes/gather_plan.h"
#include "../src/modes/jensen1996_settings.h"
#include "../src/modes/render.h"
#include "../src/modes/surface.h"
#include "../src/photon/estimate.h"
#include "../src/photon/trace.h"

#define CONE_K 1.0 /* Eq. 4's filter constant: "k = 1. This value generally works very well" */

/* ---- Pass 1: the photon maps (Sec. 3) ---- */

struct photon_maps {
    struct kdtree *global;      /* D and I photons (and caustic ones: L S+ D is in L_i,d at
                                   a point that reflects it diffusely again)             */
    struct kdtree *caustic;     /* L S+ D; NULL when nothing is specular                  */
    struct kdtree **visibility; /* per light, its D and S photons (Fig. 1)                */
    size_t n_lights;
};

/* Where the global trace's photons go: all but the shadow photons to the global map, the
 * direct and shadow photons also to their light's visibility map. */
struct global_trace {
    struct photon_trace global;
    struct photon_trace *visibility;
};

static int store_global(void *context, const struct photon_event *e)
{
    struct global_trace *gt = context;
    if (e->kind != PHOTON_SHADOW && photon_trace_store(&gt->global, MAX_PHOTONS, e) < 0)
        return -1;
    if ((e->kind & (PHOTON_DIRECT | PHOTON_SHADOW)) &&
        photon_trace_store(&gt->visibility[e->light], MAX_PHOTONS, e) < 0)
        return -1;
    return 0;
}

static struct trace_settings photon_pass(uint64_t seed, uint64_t pass, size_t n_emit,
                                         unsigned store)
{
    struct trace_settings ts;
    memset(&ts, 0, sizeof ts);
    ts.seed = seed;
    ts.pass = pass;
    ts.n_emit = n_emit;
    ts.max_stored = MAX_PHOTONS;
    ts.store = store;
    ts.max_depth = MAX_DEPTH_LIMIT;
    ts.by_parts = 1; /* a bounce leaves through f_r,d or f_r,s; caustic: f_r,s's alone */
    return ts;
}

/* The global map, "emitting photons towards all objects", with the shadow photons. */
static int trace_global_map(const struct scene *scene, uint64_t seed, size_t photons,
                            struct photon_maps *maps)
{
    struct trace_settings ts = photon_pass(seed, 0, photons, PHOTON_MAP_GLOBAL | PHOTON_SHADOW);
    struct global_trace gt;
    memset(&gt, 0, sizeof gt);
    maps->n_lights = scene->n_lights;
    gt.visibility = xcalloc(scene->n_lights + 1, sizeof *gt.visibility, "literal traces");
    struct photon_sink sink = {store_global, &gt};
    unsigned long long rays = 0;
    int status = trace_photons_into(scene, &ts, &sink, &rays);
    maps->global = balance_kdtree(gt.global.photons, gt.global.n_photons);
    maps->visibility = xcalloc(scene->n_lights + 1, sizeof *maps->visibility, "literal maps");
    for (size_t l = 0; l < scene->n_lights; l++)
        maps->visibility[l] = balance_kdtree(gt.visibility[l].photons,
                                             gt.visibility[l].n_photons);
    xfree(gt.visibility);
    return status;
}

/* The caustic map, "emitting photons towards the specular objects in the scene and
 * storing these as they hit diffuse surfaces"; none when nothing is specular. */
static int trace_caustic_map(const struct scene *scene, uint64_t seed, size_t photons,
                             struct photon_maps *maps)
{
    maps->caustic = NULL;
    if (photons == 0 || scene->n_materials == 0)
        return 0;
    struct bounding_sphere *spheres = xmalloc(scene->n_materials, sizeof *spheres, "targets");
    struct emission_targets targets = {spheres, specular_targets(scene, spheres)};
    int status = 0;
    if (targets.n_spheres > 0) {
        struct trace_settings ts = photon_pass(seed, 1, photons, PHOTON_MAP_CAUSTIC);
        struct photon_trace traced;
        struct error err;
        ts.targets = &targets;
        status = trace_photons(scene, &ts, &traced, &err);
        if (status == 0)
            maps->caustic = balance_kdtree(traced.photons, traced.n_photons);
    }
    xfree(spheres);
    return status;
}

/* ---- Pass 2: rendering (Sec. 4) ---- */

enum evaluation { ACCURATE, CORNER, APPROXIMATE }; /* CORNER: accurate, a gather ray's end */
enum emission_rule { COUNTED, SKIP_DIRECT, SKIP_ALL }; /* the emission a ray may add (above) */

struct path {
    struct vec3 beta;     /* throughput since the eye: its weight              */
    int depth;            /* reflections so far                                */
    enum evaluation eval; /* how the surface the ray reaches is evaluated      */
    enum emission_rule rule;
    int branched;         /* whether it already split into glossy_rays rays    */
};

struct pass2 {
    const struct scene *scene;
    const struct literal_jensen1996_settings *ls;
    struct photon_maps maps;
    struct nearest *nn;             /* scratch of a photon search                       */
    struct irradiance_cache *cache; /* the irradiance gradient cache's records          */
    struct gather_plan plan;        /* a final gather's strata and rays                 */
};

static struct vec3 radiance(const struct pass2 *p2, struct ray ray, struct path path,
                            struct rng *rng);
static struct vec3 surface_radiance(const struct pass2 *p2, const struct surface *s,
                                    struct path path, struct rng *rng);

/* Eq. 3 (cone_k 0) or Eq. 5 (cone_k >= 1) from map's k nearest photons through f_r,d;
 * *r2, when asked, the squared radius of the sphere that held them. */
static struct vec3 estimate(const struct pass2 *p2, const struct kdtree *map, size_t k,
                            double cone_k, const struct surface *s, const struct material *f,
                            const struct shading_frame *frame, double *r2)
{
    struct estimate_point at = {s->p, s->ng, s->wo, f, frame, !s->front};
    struct estimate_settings es = {k, HUGE_VAL, cone_k, 0, 0};
    struct vec3 l = radiance_estimate(map, &at, &es, p2->nn);
    if (r2 != NULL)
        *r2 = p2->nn->r2;
    return l;
}

/* 4.1: whether light i's sample ls is seen from s. "We only use shadow rays in situations
 * where the nearest photons [...] contains a mixture of direct illumination photons and
 * shadow photons or if the number of illumination and shadow photons located is too low." */
static int light_visible(const struct pass2 *p2, size_t i, const struct surface *s,
                         const struct light_sample *ls)
{
    struct nearest *nn = p2->nn;
    size_t direct = 0, shadow = 0;
    locate_photons(p2->maps.visibility[i], s->p, HUGE_VAL, J96_VISIBILITY_PHOTONS, nn);
    for (size_t j = 0; j < nn->found; j++)
        if (!(vec3_dot(photon_direction(nn->photon[j]), s->ng) > 0))
            continue; /* it arrived at the other side of a thin wall */
        else if (nn->photon[j]->flags & PHOTON_SHADOW)
            shadow++;
        else
            direct++;
    if (2 * (direct + shadow) >= J96_VISIBILITY_PHOTONS && !(direct > 0 && shadow > 0))
        return shadow == 0;
    return !light_blocked(p2->scene, s, ls);
}

/* Eq. 2's first term, accurately: one sample of each light through f (all of f_r, or
 * f_r,d at a gather ray's end). */
static struct vec3 direct_illumination(const struct pass2 *p2, const struct surface *s,
                                       const struct material *f,
                                       const struct shading_frame *frame, struct rng *rng)
{
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < p2->scene->n_lights; i++) {
        double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
        struct light_sample ls;
        struct vec3 contribution;
        if (light_contribution(&p2->scene->lights[i], s, f, frame, u1, u2, &ls,
                               &contribution) && light_visible(p2, i, s, &ls))
            sum = vec3_add(sum, contribution);
    }
    return sum;
}

/* Eq. 2's second term: Monte Carlo through f_r,s, each ray sampled from it, Russian
 * roulette on the weight after ROULETTE_DEPTH reflections. The surface the ray reaches
 * is accurate while the path is ("a few specular reflections") and its weight not low. */
static struct vec3 specular_reflection(const struct pass2 *p2, const struct surface *s,
                                       const struct material *f_s,
                                       const struct shading_frame *frame, struct path path,
                                       struct rng *rng)
{
    if (path.depth >= MAX_DEPTH_LIMIT)
        return vec3_zero();
    int glossy = brdf_has_non_delta(f_s);
    int n = path.eval == ACCURATE && glossy && !path.branched ? p2->ls->glossy_rays : 1;
    struct vec3 sum = vec3_zero();
    for (int r = 0; r < n; r++) {
        double u[3];
        struct brdf_sample bs;
        rng_uniforms(rng, u, 3);
        if (!brdf_sample(f_s, frame, s->wo, u, &bs))
            continue;
        struct vec3 beta = vec3_mul(path.beta, bs.weight);
        double q = roulette_odds(beta, path.depth);
        if (q < 1 && !(rng_uniform(rng) < q))
            continue;
        struct path next = {vec3_scale(beta, 1.0 / (n * q)), path.depth + 1, APPROXIMATE,
                            COUNTED, path.branched || n > 1};
        if (path.eval == ACCURATE && vec3_luminance(beta) >= p2->ls->accurate_weight)
            next.eval = ACCURATE;
        if (path.rule == SKIP_ALL)
            next.rule = SKIP_ALL; /* still on a gather ray's chain of f_r,s reflections */
        else if (!bs.delta && path.eval != APPROXIMATE)
            next.rule = SKIP_DIRECT; /* the lights seen through this lobe were sampled */
        struct ray ray = surface_ray(s, bs.wi, bs.transmitted);
        sum = vec3_add(sum, vec3_mul(vec3_scale(bs.weight, 1.0 / (n * q)),
                                     radiance(p2, ray, next, rng)));
    }
    return sum;
}

/* Radiance arriving along a gather ray that met s at distance d: accurately (a corner)
 * when d is below the threshold, else approximately. */
static struct vec3 gathered_radiance(const struct pass2 *p2, const struct surface *s,
                                     double d, struct path path, struct rng *rng)
{
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct brdf_split split = brdf_split(s->material);
    double r2 = 0.0, threshold = p2->ls->accurate_distance;
    struct vec3 l = vec3_zero();
    if (split.has_diffuse)
        l = estimate(p2, p2->maps.global, p2->ls->global_gather, 0, s, &split.diffuse, &frame,
                     &r2);
    if (path.eval == ACCURATE && d * d < threshold * threshold * r2) {
        path.eval = CORNER;
        return surface_radiance(p2, s, path, rng);
    }
    path.eval = APPROXIMATE;
    if (split.has_specular)
        l = vec3_add(l, specular_reflection(p2, s, &split.specular, &frame, path, rng));
    return l;
}

/* Jensen 1995's importance on the gather's strata: the flux of the N nearest global
 * photons arriving through each, times f_r,d, into share[]; returns their sum. */
static double importance(const struct pass2 *p2, const struct surface *s,
                         const struct material *f_d, const struct shading_frame *frame,
                         double *share)
{
    const struct gather_plan *plan = &p2->plan;
    double total = 0.0;
    for (int i = 0; i < plan->theta * plan->phi; i++)
        share[i] = 0.0;
    locate_photons(p2->maps.global, s->p, HUGE_VAL, p2->ls->global_gather, p2->nn);
    for (size_t i = 0; i < p2->nn->found; i++) {
        struct vec3 wi = photon_direction(p2->nn->photon[i]);
        if (!(vec3_dot(wi, s->ng) > 0) || !(vec3_dot(wi, frame->n) > 0))
            continue;
        struct vec3 local = vec3(vec3_dot(wi, frame->t), vec3_dot(wi, frame->b),
                                 vec3_dot(wi, frame->n));
        int j, k;
        stratum_of(plan->theta, plan->phi, local, &j, &k);
        double w = vec3_luminance(vec3_mul(photon_power(p2->nn->photon[i]),
                                           brdf_eval(f_d, frame, s->wo, wi)));
        share[j * plan->phi + k] += w;
        total += w;
    }
    return total;
}

/* The final gather at s: each stratum's mean radiance and nearest hit into strata[], and,
 * when reflected is not NULL, its mean f_r,d L there. */
static void final_gather(const struct pass2 *p2, const struct surface *s,
                         const struct material *f_d, const struct shading_frame *frame,
                         struct path path, struct rng *rng, struct stratum_sample *strata,
                         struct vec3 *reflected)
{
    const struct gather_plan *plan = &p2->plan;
    int mn = plan->theta * plan->phi;
    double *share = xmalloc((size_t)mn, sizeof *share, "literal gather");
    int *rays_in = xmalloc((size_t)mn, sizeof *rays_in, "literal gather");
    allot_rays(plan, importance(p2, s, f_d, frame, share), share, rays_in);
    path.depth++;
    path.rule = SKIP_ALL;
    for (int i = 0; i < mn; i++) {
        struct vec3 sum = vec3_zero(), f_sum = vec3_zero();
        double nearest = INFINITY;
        for (int r = 0; r < rays_in[i]; r++) {
            struct vec3 wi;
            struct surface at;
            double t;
            struct render_counters counters = {0};
            if (!gather_direction(frame, s->ng, plan->theta, plan->phi, i / plan->phi,
                                  i % plan->phi, rng, &wi))
                continue; /* below the surface: no light arrives */
            if (!ray_surface(p2->scene, surface_ray(s, wi, 0), &counters, &at, &t))
                continue; /* the sky: a light, sampled in the direct term */
            struct vec3 li = gathered_radiance(p2, &at, t, path, rng);
            nearest = fmin(nearest, t);
            sum = vec3_add(sum, li);
            if (reflected != NULL)
                f_sum = vec3_add(f_sum, vec3_mul(brdf_eval(f_d, frame, s->wo, wi), li));
        }
        strata[i].radiance = vec3_scale(sum, 1.0 / rays_in[i]);
        strata[i].distance = nearest;
        if (reflected != NULL)
            reflected[i] = vec3_scale(f_sum, 1.0 / rays_in[i]);
    }
    xfree(share);
    xfree(rays_in);
}

/* Eq. 2's fourth term, accurately. Lambertian: rho / pi times the irradiance, interpolated
 * from the cache's records where one is usable, else a final gather's, kept as a new
 * record. Otherwise a final gather of f_r,d L. */
static struct vec3 soft_indirect(const struct pass2 *p2, const struct surface *s,
                                 const struct brdf_split *split,
                                 const struct shading_frame *frame, struct path path,
                                 struct rng *rng)
{
    const struct gather_plan *plan = &p2->plan;
    size_t mn = (size_t)plan->theta * (size_t)plan->phi;
    struct vec3 e, l;
    if (split->lambertian &&
        vec3_max_component(brdf_albedo(&split->diffuse, frame, s->wo)) <= 0)
        return vec3_zero(); /* wo below the shading normal: f_r,d reflects nothing */
    if (split->lambertian &&
        irradiance_cache_lookup(p2->cache, s->p, frame->n, p2->ls->accuracy, &e))
        return diffuse_reflection(s, &split->diffuse, frame, e);
    struct stratum_sample *strata = xmalloc(mn, sizeof *strata, "literal strata");
    struct vec3 *reflected = split->lambertian ? NULL : xmalloc(mn, sizeof *reflected, "f L");
    final_gather(p2, s, &split->diffuse, frame, path, rng, strata, reflected);
    if (split->lambertian) {
        struct record_reach reach = record_reach_at(&p2->scene->camera, s->p, frame->n,
                                                    p2->ls->accuracy,
                                                    scene_diagonal(p2->scene), 0, 0);
        struct irradiance_record record = irradiance_record_of(
            s->p, frame->t, frame->b, frame->n, plan->theta, plan->phi, strata, reach);
        irradiance_cache_add(p2->cache, &record);
        l = diffuse_reflection(s, &split->diffuse, frame, record.e);
    } else {
        l = strata_integral(plan, reflected);
    }
    xfree(strata);
    xfree(reflected);
    return l;
}

/* Radiance leaving s towards s->wo on path: Eq. 2, term by term, as path.eval says. */
static struct vec3 surface_radiance(const struct pass2 *p2, const struct surface *s,
                                    struct path path, struct rng *rng)
{
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct brdf_split split = brdf_split(s->material);
    struct vec3 l = path.rule == COUNTED ? surface_emission(s) : vec3_zero();
    if (path.eval == APPROXIMATE) {
        if (split.has_diffuse)
            l = vec3_add(l, estimate(p2, p2->maps.global, p2->ls->global_gather, 0, s,
                                     &split.diffuse, &frame, NULL));
    } else {
        if (brdf_has_non_delta(s->material))
            l = vec3_add(l, direct_illumination(p2, s, path.rule == SKIP_ALL ? &split.diffuse
                                                                             : s->material,
                                                &frame, rng));
        if (split.has_diffuse && p2->maps.caustic != NULL)
            l = vec3_add(l, estimate(p2, p2->maps.caustic, p2->ls->caustic_gather, CONE_K, s,
                                     &split.diffuse, &frame, NULL));
        if (split.has_diffuse)
            l = vec3_add(l, soft_indirect(p2, s, &split, &frame, path, rng));
    }
    if (split.has_specular)
        l = vec3_add(l, specular_reflection(p2, s, &split.specular, &frame, path, rng));
    return l;
}

/* Radiance arriving along ray on path; where it leaves the scene, the sky's if the path
 * may add emission. */
static struct vec3 radiance(const struct pass2 *p2, struct ray ray, struct path path,
                            struct rng *rng)
{
    struct surface s;
    double t;
    struct render_counters counters = {0};
    if (!ray_surface(p2->scene, ray, &counters, &s, &t))
        return path.rule == COUNTED ? p2->scene->background : vec3_zero();
    return surface_radiance(p2, &s, path, rng);
}

static void free_maps(struct photon_maps *maps)
{
    kdtree_free(maps->global);
    kdtree_free(maps->caustic);
    for (size_t l = 0; l < maps->n_lights; l++)
        kdtree_free(maps->visibility[l]);
    xfree(maps->visibility);
}

struct image *literal_jensen1996(const struct scene *scene,
                                 const struct literal_jensen1996_settings *ls)
{
    struct pass2 p2;
    memset(&p2, 0, sizeof p2);
    p2.scene = scene;
    p2.ls = ls;
    int failed = trace_global_map(scene, ls->seed, ls->global_photons, &p2.maps) < 0;
    failed |= trace_caustic_map(scene, ls->seed, ls->caustic_photons, &p2.maps) < 0;
    if (failed) {
        free_maps(&p2.maps);
        return NULL;
    }
    size_t k = ls->global_gather > ls->caustic_gather ? ls->global_gather : ls->caustic_gather;
    p2.nn = nearest_create(k > J96_VISIBILITY_PHOTONS ? k : J96_VISIBILITY_PHOTONS);
    p2.cache = irradiance_cache_create(geometry_bounds(scene->geometry), ls->accuracy);
    p2.plan = gather_plan_of(ls->gather_rays);
    struct image *image = image_create(scene->width, scene->height);
    for (int y = 0; y < scene->height; y++)
        for (int x = 0; x < scene->width; x++) {
            struct vec3 sum = vec3_zero();
            for (int s = 0; s < ls->spp; s++) {
                struct rng rng;
                struct ray ray = camera_sample(scene, ls->seed, x, y, s, &rng);
                struct path eye = {{1.0, 1.0, 1.0}, 0, ACCURATE, COUNTED, 0};
                sum = vec3_add(sum, radiance(&p2, ray, eye, &rng));
            }
            image->pixels[(size_t)y * scene->width + x] = vec3_scale(sum, 1.0 / ls->spp);
        }
    irradiance_cache_free(p2.cache);
    nearest_free(p2.nn);
    free_maps(&p2.maps);
    return image;
}
