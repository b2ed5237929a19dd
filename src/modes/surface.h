/*
 * modes/surface.h -- a hit as a mode sees it: normals turned towards the viewer.
 *
 * Geometry reports normals on the primitive's front side; which side a ray came from is
 * a rendering question, answered here once for every mode. Surfaces reflect on both sides
 * (a wall is lit from whichever side the light is on); emitters emit from the front only.
 */
#ifndef PHOTON_SURFACE_H
#define PHOTON_SURFACE_H

#include "../base/rng.h"
#include "../scene/brdf.h"
#include "../scene/scene.h"
#include "render_counters.h"

#define ROULETTE_DEPTH 3 /* bounces before roulette, as in pbrt: short paths are cheap */

struct surface {
    struct vec3 p;                    /* hit position                                  */
    struct vec3 ng;                   /* unit geometric normal on the side of wo       */
    struct vec3 ns;                   /* unit shading normal on the side of wo         */
    struct vec3 wo;                   /* unit direction back along the incoming ray    */
    int front;                        /* whether wo is on the primitive's front side   */
    const struct material *material;  /* borrowed from the scene                       */
    int prim;                         /* the primitive hit                             */
    double u, v;                      /* where on it (struct hit)                      */
};

/* The surface at hit as seen along unit direction wo (pointing away from the surface). */
static inline struct surface surface_at(const struct scene *scene, const struct hit *hit,
                                        struct vec3 wo)
{
    struct surface s;
    s.p = hit->p;
    s.wo = wo;
    s.front = vec3_dot(wo, hit->ng) > 0;
    s.ng = s.front ? hit->ng : vec3_neg(hit->ng);
    s.ns = s.front ? hit->ns : vec3_neg(hit->ns);
    s.material = &scene->materials[hit->material];
    s.prim = hit->prim;
    s.u = hit->u;
    s.v = hit->v;
    return s;
}

/* Casts ray, counting it: 1 with *s the surface it reaches (seen back along the ray) and
 * *t the distance to it, or 0 when it leaves the scene. */
static inline int ray_surface(const struct scene *scene, struct ray ray,
                              struct render_counters *counters, struct surface *s, double *t)
{
    struct hit hit;
    counters->rays++;
    if (!scene_intersect(scene, ray, INFINITY, &hit))
        return 0;
    *s = surface_at(scene, &hit, vec3_neg(ray.dir));
    *t = hit.t;
    return 1;
}

/* Radiance the surface emits towards wo: Le on an emitter's front side (and its back
 * side if it is two-sided), else zero. */
static inline struct vec3 surface_emission(const struct surface *s)
{
    return s->front || s->material->two_sided ? s->material->emission : vec3_zero();
}

/* Radiance that a Lambertian part (or one taken as Lambertian) reflects towards s->wo from
 * irradiance e: albedo / pi times e, and zero where s->wo lies below the shading normal,
 * where the BRDF reflects nothing (brdf_eval(); pt sees such a point black). */
static inline struct vec3 diffuse_reflection(const struct surface *s,
                                             const struct material *diffuse,
                                             const struct shading_frame *frame, struct vec3 e)
{
    return vec3_mul(brdf_albedo(diffuse, frame, s->wo), vec3_scale(e, 1.0 / PI));
}

/* The ray leaving s in unit direction wi: from the side of the surface wi goes to, so it
 * does not hit the surface it starts on (through it, when transmitted). */
static inline struct ray surface_ray(const struct surface *s, struct vec3 wi, int transmitted)
{
    struct vec3 side = transmitted ? vec3_neg(s->ng) : s->ng;
    return make_ray(offset_origin(s->p, side), wi);
}

/* Samples s's BRDF; if the lobe is a delta one (mirror, refraction), multiplies *beta by
 * its weight, sets *ray to the reflected or refracted ray and returns 1. A non-delta
 * lobe returns 0: for the photon modes, the light it would bring is what the photons at
 * s already hold. */
static inline int specular_bounce(const struct surface *s, const struct shading_frame *frame,
                                  struct rng *rng, struct vec3 *beta, struct ray *ray)
{
    double u[3];
    rng_uniforms(rng, u, 3);
    struct brdf_sample bs;
    if (!brdf_sample(s->material, frame, s->wo, u, &bs) || !bs.delta)
        return 0;
    *beta = vec3_mul(*beta, bs.weight);
    *ray = surface_ray(s, bs.wi, bs.transmitted);
    return 1;
}

/* One sample of light l seen from s, with uniform numbers u1, u2: *contribution is the
 * radiance reflected towards s->wo through m's non-delta part if nothing blocks the light,
 * f_r Li cos / pdf, and *ls the sample (wi and distance: the shadow ray's segment).
 * Returns 0 when the sample can bring nothing: the light is behind the surface or cannot
 * see s, or f_r is zero there. */
static inline int light_contribution(const struct light *l, const struct surface *s,
                                     const struct material *m,
                                     const struct shading_frame *frame, double u1, double u2,
                                     struct light_sample *ls, struct vec3 *contribution)
{
    if (!light_sample(l, s->p, s->ns, u1, u2, ls))
        return 0;
    double cos_theta = vec3_dot(s->ns, ls->wi);
    if (cos_theta <= 0 || vec3_dot(s->ng, ls->wi) <= 0)
        return 0; /* the light is behind the surface */
    struct vec3 fr = brdf_eval(m, frame, s->wo, ls->wi);
    if (vec3_max_component(fr) <= 0)
        return 0;
    *contribution = vec3_scale(vec3_mul(fr, ls->li), cos_theta / ls->pdf); /* pdf > 0 */
    return 1;
}

/* Veach 1997 Eq. 9.13 with beta = 2: the weight of strategy a against strategy b, each
 * given as its number of samples times its solid-angle pdf of the same direction. */
static inline double power_heuristic(double pdf_a, double pdf_b)
{
    double a2 = pdf_a * pdf_a, b2 = pdf_b * pdf_b;
    return a2 + b2 > 0 ? a2 / (a2 + b2) : 0.0;
}

/* Whether the shadow ray of light sample ls from s is blocked (the sky's, of infinite
 * length, by anything). */
static inline int light_blocked(const struct scene *scene, const struct surface *s,
                                const struct light_sample *ls)
{
    return scene_occluded(scene, offset_origin(s->p, s->ng), ls->wi, ls->distance);
}

/* Russian roulette's survival odds for a camera path with throughput beta after depth
 * bounces: 1 before ROULETTE_DEPTH, then q = min(1, largest channel of beta) (0 for a
 * zero or NaN throughput). */
static inline double roulette_odds(struct vec3 beta, int depth)
{
    if (depth < ROULETTE_DEPTH)
        return 1.0;
    double q = fmin(1.0, vec3_max_component(beta));
    return q > 0 ? q : 0.0;
}

/* Russian roulette on a camera path with the odds above: 0 ends the path; otherwise
 * *beta is divided by q, so the estimate stays unbiased. A number is drawn only once
 * roulette applies. */
static inline int survives_roulette(struct vec3 *beta, int depth, struct rng *rng)
{
    if (depth < ROULETTE_DEPTH)
        return 1;
    double q = roulette_odds(*beta, depth);
    if (!(rng_uniform(rng) < q))
        return 0;
    *beta = vec3_scale(*beta, 1.0 / q); /* q > 0 here: a uniform number was below it */
    return 1;
}

#endif
