/*
 * modes/direct.c -- `--mode direct`: direct lighting plus ideal specular paths.
 *
 * Whitted's ray tracer (1980) with area lights: where the BRDF has a non-delta part, one
 * shadow-tested sample of every light (L = Le + sum over lights of f_r Li cos / pdf);
 * where it has a delta lobe, the ideal specular ray: at a mirror the reflected one, at
 * glass the reflected or the refracted one chosen with the exact Fresnel probability,
 * which keeps the estimate unbiased without tracing both. Light that
 * reaches a diffuse surface by way of other diffuse surfaces or of specular ones
 * (indirect light, caustics) is absent by design: that is what the other modes add.
 *
 * An emitter contributes when seen directly or through specular surfaces; the light
 * samples at diffuse surfaces account for it everywhere else, so nothing is counted twice.
 */
#include "direct.h"

#include "../scene/brdf.h"
#include "surface.h"

struct direct_mode {
    const struct scene *scene; /* borrowed */
    int max_depth;
};

/* Reflected radiance through the BRDF's non-delta part from one sample of each light. */
static struct vec3 direct_lighting(const struct scene *scene, const struct surface *s,
                                   const struct shading_frame *frame, struct rng *rng,
                                   struct render_counters *counters)
{
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < scene->n_lights; i++) {
        struct light_sample ls;
        struct vec3 contribution;
        double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
        if (!light_contribution(&scene->lights[i], s, s->material, frame, u1, u2, &ls,
                                &contribution))
            continue;
        counters->rays++;
        if (!light_blocked(scene, s, &ls))
            sum = vec3_add(sum, contribution);
    }
    return sum;
}

static struct vec3 trace(const struct direct_mode *dm, struct ray ray, int depth,
                         struct rng *rng, struct render_counters *counters);

/* Whitted's specular ray: one lobe sampled from the BRDF; if it is a delta lobe (mirror
 * reflection, refraction), its ray is traced and weighted by reflectance / probability,
 * so mixtures of lobes stay unbiased. A non-delta lobe adds nothing here: light arriving
 * through it is what direct_lighting() estimates, or what this mode leaves out. */
static struct vec3 specular_ray(const struct direct_mode *dm, const struct surface *s,
                                const struct shading_frame *frame, int depth, struct rng *rng,
                                struct render_counters *counters)
{
    double u[3];
    rng_uniforms(rng, u, 3);
    struct brdf_sample bs;
    if (!brdf_sample(s->material, frame, s->wo, u, &bs) || !bs.delta)
        return vec3_zero();
    struct ray r = surface_ray(s, bs.wi, bs.transmitted);
    return vec3_mul(bs.weight, trace(dm, r, depth + 1, rng, counters));
}

static struct vec3 scatter(const struct direct_mode *dm, const struct surface *s, int depth,
                           struct rng *rng, struct render_counters *counters)
{
    const struct material *m = s->material;
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct vec3 l = vec3_zero();
    if (brdf_has_non_delta(m))
        l = direct_lighting(dm->scene, s, &frame, rng, counters);
    if (brdf_has_delta(m) && depth < dm->max_depth)
        l = vec3_add(l, specular_ray(dm, s, &frame, depth, rng, counters));
    return l;
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

static struct vec3 direct_radiance(const void *mode, struct ray ray,
                                   const struct first_bounce *first, struct rng *rng,
                                   struct render_counters *counters)
{
    (void)first; /* its first bounce draws from the stream */
    return trace(mode, ray, 0, rng, counters);
}

struct render_result render_direct(const struct scene *scene, const struct render_settings *rs,
                                   int want_variance, const struct checkpoint *checkpoint,
                                   struct render_counters *counters)
{
    struct direct_mode dm;
    dm.scene = scene;
    dm.max_depth = rs->max_depth;
    struct radiance_estimator estimator;
    estimator.radiance = direct_radiance;
    estimator.mode = &dm;
    estimator.sample_taken = NULL;
    return render_pixels(scene, rs, estimator, want_variance, checkpoint, counters);
}
