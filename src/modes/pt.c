/*
 * modes/pt.c -- `--mode pt`: unbiased path tracing (Kajiya 1986), the ground truth.
 *
 * Each camera sample follows one path. At every surface with a non-delta BRDF, one light
 * is sampled (picked by power) and shadow-tested: next-event estimation. The path then
 * continues in a direction sampled from the BRDF. Emission found by that BRDF-sampled ray
 * and the light sample estimate the same light twice, so both are weighted by Veach's
 * power heuristic (multiple importance sampling, Veach 1997, Sec. 9.2): each weight is
 * pdf_a^2 / (pdf_a^2 + pdf_b^2) for the two strategies' solid-angle densities of the
 * same direction, and the weights of the two sum to one. Point lights and delta lobes
 * have one strategy only and weight 1. The sky is a light like the others: sampled
 * about the normal, and found by a BRDF-sampled ray that leaves the scene, the two
 * weighted alike. After ROULETTE_DEPTH bounces Russian roulette ends
 * a path with probability 1 - q, q = min(1, max channel of the throughput), and divides
 * survivors by q: unbiased, and no path is cut short by a depth limit it could exceed in
 * practice (--max-depth defaults to the limit, 1000). Nothing is clamped.
 *
 * At the first surface the BRDF-sampled direction comes from the camera sample's
 * stratified uniforms (first_bounce_sample(), render.h), the rest from its stream: a
 * pixel's paths then spread over the hemisphere above the surface it sees as its points
 * spread over the pixel. The light sample's point is not stratified so: the batches
 * pixel_error.h states the error from, each stratified on its own, would then err far
 * less together than their spread says (area-over-floor at 16 samples: the bound 5.9
 * times the error, median over 8 x 8 blocks, where it is 2.6).
 */
#include "pt.h"

#include "../scene/brdf.h"
#include "surface.h"


struct pt_mode {
    const struct scene *scene; /* borrowed */
    int max_depth;
};

/* Where a path has been, for weighting the emission its next ray finds. */
struct path_vertex {
    struct vec3 p;  /* the last scattering point                                   */
    struct vec3 n;  /* its shading normal on the side the path left it by          */
    double pdf;     /* solid-angle pdf of the direction sampled there              */
    int delta;      /* whether it was a delta lobe (or the camera): no MIS         */
};

/* Next-event estimation: reflected radiance from one light sample, MIS-weighted; the
 * light's point from the uniforms u (two). */
static struct vec3 sample_one_light(const struct scene *scene, const struct surface *s,
                                    const struct shading_frame *frame, const double u[2],
                                    struct rng *rng, struct render_counters *counters)
{
    double pick;
    int index = scene_pick_light(scene, rng_uniform(rng), &pick);
    struct light_sample ls;
    if (index < 0 || !light_sample(&scene->lights[index], s->p, s->ns, u[0], u[1], &ls))
        return vec3_zero();
    double cos_theta = vec3_dot(s->ns, ls.wi);
    if (cos_theta <= 0 || vec3_dot(s->ng, ls.wi) <= 0)
        return vec3_zero(); /* the light is behind the surface */
    struct vec3 fr = brdf_eval(s->material, frame, s->wo, ls.wi);
    if (vec3_max_component(fr) <= 0)
        return vec3_zero();
    counters->rays++;
    if (scene_occluded(scene, offset_origin(s->p, s->ng), ls.wi, ls.distance))
        return vec3_zero();
    double pdf_light = pick * ls.pdf; /* > 0: pick > 0 and light_sample() succeeded */
    double weight = scene->lights[index].kind == LIGHT_POINT
                        ? 1.0
                        : power_heuristic(pdf_light, brdf_pdf(s->material, frame, s->wo, ls.wi));
    return vec3_scale(vec3_mul(fr, ls.li), cos_theta * weight / pdf_light);
}

/* Radiance le of light `light` that a BRDF-sampled ray from the previous vertex found
 * along unit wi, at q on the light (unused for the sky), MIS-weighted against having
 * sampled the same light there. */
static struct vec3 light_found(const struct scene *scene, int light, struct vec3 le,
                               struct vec3 q, struct vec3 wi,
                               const struct path_vertex *previous)
{
    if (previous->delta || light < 0 || vec3_max_component(le) <= 0)
        return le;
    double pdf_light = scene_light_probability(scene, light) *
                       light_pdf(&scene->lights[light], previous->p, previous->n, q, wi);
    return vec3_scale(le, power_heuristic(previous->pdf, pdf_light));
}

/* Emitted radiance that a BRDF-sampled ray found at s. */
static struct vec3 emission_found(const struct scene *scene, const struct surface *s,
                                  const struct path_vertex *previous)
{
    return light_found(scene, scene->light_of_prim[s->prim], surface_emission(s), s->p,
                       vec3_neg(s->wo), previous);
}

/* A vertex's uniforms: light_u for its light sample's point, u for its BRDF sample (u[0]
 * the lobe, u[1] and u[2] the direction: brdf.h), the direction's from first's stratified
 * ones where given (the first surface), the rest from the stream. */
static void vertex_uniforms(const struct first_bounce *first, struct rng *rng,
                            double light_u[2], double u[3])
{
    rng_uniforms(rng, light_u, 2);
    rng_uniforms(rng, u, 3);
    if (first != NULL) {
        u[1] = first->direction[0];
        u[2] = first->direction[1];
    }
}

static struct vec3 trace_path(const struct pt_mode *pt, struct ray ray,
                              const struct first_bounce *first, struct rng *rng,
                              struct render_counters *counters)
{
    const struct scene *scene = pt->scene;
    struct vec3 l = vec3_zero(), beta = vec3(1, 1, 1);
    struct path_vertex previous = {{0, 0, 0}, {0, 0, 0}, 0.0, 1}; /* the camera: a delta */
    for (int depth = 0;; depth++) {
        struct hit hit;
        counters->rays++;
        if (!scene_intersect(scene, ray, INFINITY, &hit))
            return vec3_add(l, vec3_mul(beta, light_found(scene, scene->sky, scene->background,
                                                          ray.origin, ray.dir, &previous)));
        struct surface s = surface_at(scene, &hit, vec3_neg(ray.dir));
        l = vec3_add(l, vec3_mul(beta, emission_found(scene, &s, &previous)));
        if (depth >= pt->max_depth)
            return l;
        struct shading_frame frame = shading_frame_from_normal(s.ns, s.front,
                                                               TRANSPORT_RADIANCE);
        double light_u[2], u[3];
        vertex_uniforms(depth == 0 ? first : NULL, rng, light_u, u);
        if (brdf_has_non_delta(s.material))
            l = vec3_add(l, vec3_mul(beta, sample_one_light(scene, &s, &frame, light_u, rng,
                                                            counters)));
        struct brdf_sample bs;
        if (!brdf_sample(s.material, &frame, s.wo, u, &bs))
            return l;
        beta = vec3_mul(beta, bs.weight);
        previous.p = s.p;
        previous.n = s.ns;
        previous.pdf = bs.pdf;
        previous.delta = bs.delta;
        ray = surface_ray(&s, bs.wi, bs.transmitted);
        if (!survives_roulette(&beta, depth + 1, rng))
            return l;
    }
}

static struct vec3 pt_radiance(const void *mode, struct ray ray,
                               const struct first_bounce *first, struct rng *rng,
                               struct render_counters *counters)
{
    return trace_path(mode, ray, first, rng, counters);
}

int pt_finds_caustics_by_chance(const struct scene *scene)
{
    int specular = 0;
    for (size_t i = 0; i < scene->n_materials; i++)
        specular = specular || brdf_has_delta(&scene->materials[i]);
    return specular;
}

int pt_unreachable_light(const struct scene *scene)
{
    int specular = pt_finds_caustics_by_chance(scene);
    for (size_t i = 0; specular && i < scene->n_lights; i++)
        if (scene->lights[i].kind == LIGHT_POINT)
            return (int)i;
    return -1;
}

struct render_result render_pt(const struct scene *scene, const struct render_settings *rs,
                               int want_variance, const struct checkpoint *checkpoint,
                               struct render_counters *counters)
{
    struct pt_mode pt;
    pt.scene = scene;
    pt.max_depth = rs->max_depth;
    struct radiance_estimator estimator;
    estimator.radiance = pt_radiance;
    estimator.mode = &pt;
    estimator.sample_taken = NULL;
    return render_pixels(scene, rs, estimator, want_variance, checkpoint, counters);
}
