/*
 * modes/direct.c -- `--mode direct`: direct lighting plus ideal specular paths.
 *
 * Whitted's ray tracer (1980) with area lights: at a Lambertian surface, one shadow-tested
 * sample of every light (Eq. L = Le + sum_lights f_r Li cos / pdf); at a mirror, the
 * reflected ray; at glass, one of the reflected or refracted rays chosen with the exact
 * Fresnel probability, which keeps the estimate unbiased without tracing both. Light that
 * reaches a diffuse surface by way of other diffuse surfaces or of specular ones
 * (indirect light, caustics) is absent by design: that is what the other modes add.
 *
 * An emitter contributes when seen directly or through specular surfaces; the light
 * samples at diffuse surfaces account for it everywhere else, so nothing is counted twice.
 */
#include "direct.h"

#include "../scene/optics.h"
#include "surface.h"

struct direct_mode {
    const struct scene *scene; /* borrowed */
    int max_depth;
};

/* Reflected radiance at a Lambertian surface from one sample of each light. */
static struct vec3 direct_lighting(const struct scene *scene, const struct surface *s,
                                   struct rng *rng, struct render_counters *counters)
{
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < scene->n_lights; i++) {
        struct light_sample ls;
        double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
        if (!light_sample(&scene->lights[i], s->p, u1, u2, &ls))
            continue;
        double cos_theta = vec3_dot(s->ns, ls.wi);
        if (cos_theta <= 0 || vec3_dot(s->ng, ls.wi) <= 0)
            continue; /* the light is behind the surface */
        counters->rays++;
        if (scene_occluded(scene, offset_origin(s->p, s->ng), ls.wi, ls.distance))
            continue;
        sum = vec3_add(sum, vec3_scale(ls.li, cos_theta / ls.pdf)); /* pdf > 0 when sampled */
    }
    return vec3_scale(vec3_mul(s->material->rho, sum), 1.0 / PI); /* f_r = rho / pi */
}

static struct vec3 trace(const struct direct_mode *dm, struct ray ray, int depth,
                         struct rng *rng, struct render_counters *counters);

/* The ray leaving a glass surface, reflected or refracted with the Fresnel probability,
 * and its weight: 1 for reflection, 1 / eta^2 for refraction (radiance is compressed as
 * it enters a denser medium and spreads as it leaves). */
static struct ray glass_ray(const struct surface *s, struct rng *rng, double *weight)
{
    double eta = s->front ? s->material->ior : 1.0 / s->material->ior; /* n_t / n_i */
    double reflectance = fresnel_dielectric(vec3_dot(s->wo, s->ns), eta);
    struct vec3 wi;
    *weight = 1.0;
    if (rng_uniform(rng) < reflectance || !refract(s->wo, s->ns, eta, &wi))
        return make_ray(offset_origin(s->p, s->ng), reflect(s->wo, s->ns));
    *weight = 1.0 / (eta * eta);
    return make_ray(offset_origin(s->p, vec3_neg(s->ng)), wi);
}

static struct vec3 scatter(const struct direct_mode *dm, const struct surface *s, int depth,
                           struct rng *rng, struct render_counters *counters)
{
    const struct material *m = s->material;
    if (m->kind == MATERIAL_LAMBERT)
        return direct_lighting(dm->scene, s, rng, counters);
    if (depth >= dm->max_depth)
        return vec3_zero();
    if (m->kind == MATERIAL_MIRROR) {
        struct ray r = make_ray(offset_origin(s->p, s->ng), reflect(s->wo, s->ns));
        return vec3_mul(m->rho, trace(dm, r, depth + 1, rng, counters));
    }
    double weight;
    struct ray r = glass_ray(s, rng, &weight);
    return vec3_scale(trace(dm, r, depth + 1, rng, counters), weight);
}

static struct vec3 trace(const struct direct_mode *dm, struct ray ray, int depth,
                         struct rng *rng, struct render_counters *counters)
{
    struct hit hit;
    counters->rays++;
    if (!scene_intersect(dm->scene, ray, INFINITY, &hit))
        return dm->scene->background;
    struct surface s = surface_at(dm->scene, &hit, vec3_neg(ray.dir));
    return vec3_add(surface_emission(&s), scatter(dm, &s, depth, rng, counters));
}

static struct vec3 direct_radiance(const void *mode, struct ray ray, struct rng *rng,
                                   struct render_counters *counters)
{
    return trace(mode, ray, 0, rng, counters);
}

struct image *render_direct(const struct scene *scene, const struct render_settings *rs,
                            struct render_counters *counters)
{
    struct direct_mode dm;
    dm.scene = scene;
    dm.max_depth = rs->max_depth;
    struct radiance_estimator estimator;
    estimator.radiance = direct_radiance;
    estimator.mode = &dm;
    return render_pixels(scene, rs, estimator, counters);
}
