/*
 * photon/trace.c -- photon tracing (trace.h; Jensen 1996, Sec. 3).
 *
 * A photon's life: a light is picked with probability p_pick proportional to its power
 * (scene_pick_light), the light emits the photon (scene/emit.h) with power
 * Phi_l weight / (p_pick N), and the photon is followed from surface to surface. At each
 * surface that holds photons it is stored with the power it arrives with; then the
 * BRDF samples the direction it leaves in (under TRANSPORT_IMPORTANCE: power is not
 * scaled by refraction) with weight f cos / pdf (or reflectance / probability for a
 * delta lobe), and Russian roulette keeps it with probability
 *   q = min(1, max channel of the weight),
 * dividing its power by q when it survives: power <- power weight / q. For a grey
 * Lambertian surface weight = rho and q = rho, so the power stays as it was and the
 * photon is absorbed with probability 1 - rho, as the paper's roulette on the albedo;
 * for a coloured one the power takes on the surface's colour. Every step keeps the
 * expected power of what is stored equal to the flux that arrives, so estimates are
 * unbiased. Powers are computed in double and rounded once, by photon_pack().
 *
 * What the emitted powers sum to. With one light (p_pick = 1) every photon leaves with
 * exactly Phi_l / N in every channel, so N photons carry Phi_l (up to rounding). With
 * several, light l is picked with p_l = lum(Phi_l) / sum lum(Phi) (luminance, vec3.h),
 * so every photon leaves with the same luminance lum(Phi_total) / N, exactly; per
 * channel c the N photons carry sum_l n_l Phi_l,c / (p_l N) with (n_l) multinomial,
 * which is Phi_total,c in expectation, not in every trace.
 *
 * With projection maps (trace_settings.projection; Jensen and Christensen 1994, Sec. 3)
 * the maps pick the light, its patch and a cell of directions together, from photon i's
 * stratified number (i + xi) / N, and the photon leaves with Phi_l weight / N, the
 * choice of light folded into the weight (projection_map.h). Photons go only where they
 * can hit something, so N photons carry the marked share of the lights' power.
 *
 * On a smooth-shaded surface (a shading normal n_s other than the geometric n_g) the
 * BRDF integrates against |w . n_s| where a photon's power is flux through the geometric
 * surface: the stored power and the scattering weight take shading_share()'s factors
 * (scene/brdf.h; Veach 1997, Sec. 5.3), which are exactly 1 on flat-shaded surfaces.
 * Without them a surface whose shading normal tilts towards the light renders in the
 * photon map as dark as its geometric cosine says, where pt's light sample takes the
 * shading normal's (tests/test_shading.c).
 *
 * Departs from Sec. 3: a surface whose albedo is zero in every channel (the black
 * emitter the `light` keyword makes) holds no photons: they could add nothing to its own
 * estimates and would only join a neighbour's (the Cornell light hangs 0.1 mm below the
 * ceiling).
 *
 * Departs from Sec. 3: a photon whose power leaves the range of the 20-byte record
 * (photon_power_fits(): below 2^127 W per channel, not NaN) is not emitted, stored or
 * followed past where it scatters. Under the scene's limit on the lights' power
 * (MAX_LIGHT_POWER, scene.h) every photon leaves within range; only a BRDF weight above 1
 * (glossy lobes at grazing angles, or a shading normal's share), repeated over dozens of
 * bounces, could carry one out of it.
 */
#include "trace.h"

#include <assert.h>
#include <math.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/rng.h"
#include "../scene/brdf.h"
#include "projection_map.h"

#define INITIAL_CAPACITY 4096 /* records; the array grows from here up to max_stored */
#define GROWTH_DIVISOR 8      /* by an eighth each time: the array holds at most 1/8 more
                                 records than it stores (doubling could waste half), and
                                 realloc moves each record about 9 times, amortised      */

/* A surface as the photon that reaches it sees it. */
struct photon_hit {
    struct vec3 p;                   /* where it hit                                    */
    struct vec3 ng;                  /* unit geometric normal on the side of wi         */
    struct vec3 wi;                  /* unit, back towards where the photon came from   */
    struct shading_frame frame;      /* around the shading normal on the side of wi     */
    const struct material *material; /* borrowed from the scene                         */
    int prim;                        /* the primitive hit, and where on it (struct hit) */
    double u, v;
    int front;                       /* whether wi is on the primitive's front side     */
};

/* The path a photon has taken so far. */
struct photon_path {
    int light;         /* the light that emitted it          */
    struct vec3 power; /* Delta Phi it carries, W per channel */
    int specular_only; /* whether every bounce so far was specular (L S* so far): a
                          delta lobe, or with by_parts the specular part f_r,s          */
    unsigned batch;    /* its emission index modulo PHOTON_BATCHES (photon.h)          */
};

static struct photon_hit photon_hit_at(const struct scene *scene, const struct hit *hit,
                                       struct vec3 dir)
{
    struct photon_hit h;
    h.p = hit->p;
    h.wi = vec3_neg(dir);
    int front = vec3_dot(h.wi, hit->ng) > 0;
    h.ng = front ? hit->ng : vec3_neg(hit->ng);
    h.frame = shading_frame_from_normal(front ? hit->ns : vec3_neg(hit->ns), front,
                                        TRANSPORT_IMPORTANCE);
    h.material = &scene->materials[hit->material];
    h.prim = hit->prim;
    h.u = hit->u;
    h.v = hit->v;
    h.front = front;
    return h;
}

/* Whether photons are stored at h: a non-delta part that reflects something. */
static int holds_photons(const struct photon_hit *h)
{
    return brdf_has_non_delta(h->material) &&
           vec3_max_component(brdf_albedo(h->material, &h->frame, h->wi)) > 0;
}

int photons_land_at(const struct scene *scene, const struct hit *hit, struct vec3 dir)
{
    struct photon_hit h = photon_hit_at(scene, hit, dir);
    return holds_photons(&h);
}

/* The photon stored at h: what the tracer hands to its sink. */
static struct photon_event photon_event_at(const struct photon_hit *h, struct vec3 power,
                                           unsigned kind, const struct photon_path *path)
{
    struct photon_event e;
    e.light = path->light;
    e.batch = path->batch;
    e.position = h->p;
    e.normal = h->ng;
    e.wi = h->wi;
    e.power = power;
    e.kind = kind;
    e.prim = h->prim;
    e.u = h->u;
    e.v = h->v;
    e.back = !h->front;
    return e;
}

int photon_trace_store(struct photon_trace *out, size_t max_stored, const struct photon_event *e)
{
    if (out->n_photons == out->capacity) {
        if (out->capacity >= max_stored)
            return -1;
        size_t grown = out->capacity < INITIAL_CAPACITY
                           ? INITIAL_CAPACITY
                           : out->capacity + out->capacity / GROWTH_DIVISOR;
        grown = grown < max_stored ? grown : max_stored;
        out->photons = xrealloc(out->photons, grown, sizeof *out->photons, "photon map");
        out->capacity = grown;
    }
    unsigned side = e->back ? PHOTON_BACK : 0u; /* exact here; wi is rounded in the record */
    unsigned batch = e->batch << PHOTON_BATCH_SHIFT;
    out->photons[out->n_photons++] = photon_pack(e->position, e->power, e->wi,
                                                 e->kind | side | batch);
    out->n_direct += (e->kind & PHOTON_DIRECT) != 0;
    out->n_caustic += (e->kind & PHOTON_CAUSTIC) != 0;
    out->n_indirect += (e->kind & PHOTON_INDIRECT) != 0;
    out->n_shadow += (e->kind & PHOTON_SHADOW) != 0;
    return 0;
}

/* trace_photons()' sink: one array, at most max_stored photons. */
struct packing_sink {
    struct photon_trace *out;
    size_t max_stored;
};

static int pack_photon(void *context, const struct photon_event *e)
{
    struct packing_sink *ps = context;
    return photon_trace_store(ps->out, ps->max_stored, e);
}

/* Emits a photon's ray and power with its first six uniform numbers: u[0] picks the light
 * (with projection maps: the cell, stratified by the caller), u[1..5] the emission. 0 when
 * it carries nothing (no lights, a black light, a degenerate emission, nothing marked). */
static int emit_photon(const struct scene *scene, const struct trace_settings *ts,
                       const double u[6], struct ray *ray, struct photon_path *path)
{
    struct emission e;
    double pick = 1.0; /* projection maps fold the choice of light into e.weight */
    int index;
    if (ts->projection != NULL) {
        index = projection_emit(ts->projection, scene, u, &e);
        if (index < 0)
            return 0;
    } else {
        index = scene_pick_light(scene, u[0], &pick);
        if (index < 0)
            return 0;
        const struct light *l = &scene->lights[index];
        if (!(ts->targets == NULL ? light_emit(l, u + 1, &e)
                                  : light_emit_towards(l, ts->targets, u + 1, &e)))
            return 0;
    }
    path->light = index;
    /* Phi_l weight / (p_pick N): pick > 0 (scene_pick_light), N >= 1 (a photon exists) */
    path->power = vec3_scale(light_power(&scene->lights[index]),
                             e.weight / (pick * (double)ts->n_emit));
    struct vec3 origin = vec3_length2(e.normal) > 0 ? offset_origin(e.origin, e.normal)
                                                    : e.origin;
    *ray = make_ray(origin, e.dir);
    return vec3_max_component(path->power) > 0 && photon_power_fits(path->power);
}

/* Jensen and Christensen 1995: the emitted ray followed on through the surfaces behind
 * its first hit (at most max_depth of them), a zero-power shadow photon at each one that
 * holds photons. ray: the emitted ray; first: its first hit. -1 when the map is full. */
static int store_shadow_photons(const struct scene *scene, const struct trace_settings *ts,
                                struct ray ray, const struct photon_hit *first,
                                const struct photon_path *path,
                                const struct photon_sink *sink, unsigned long long *rays)
{
    struct photon_hit h = *first;
    for (int n = 0; n < ts->max_depth; n++) {
        struct hit hit;
        ray.origin = offset_origin(h.p, vec3_neg(h.ng)); /* on through the surface */
        (*rays)++;
        if (!scene_intersect(scene, ray, INFINITY, &hit))
            return 0;
        h = photon_hit_at(scene, &hit, ray.dir);
        if (holds_photons(&h)) {
            struct photon_event e = photon_event_at(&h, vec3_zero(), PHOTON_SHADOW, path);
            if (sink->store(sink->context, &e) < 0)
                return -1;
        }
    }
    return 0;
}

/* The part of the BRDF a photon leaves through with by_parts: f_r,s with probability
 * *probability, the luminance of its albedo bound towards wi over the sum of both parts'
 * (brdf_albedo()), else f_r,d. Dividing the sample's weight by the chosen part's
 * probability keeps the expected power what the whole BRDF reflects, since f_r is the sum
 * of the parts. A material with one part (Lambert, mirror, glass) takes it without a
 * random number, so its photons follow the paths they would without by_parts. NULL when
 * neither part reflects anything towards wi. */
static const struct material *chosen_part(const struct photon_hit *h,
                                          const struct brdf_split *split, struct rng *rng,
                                          double *probability, int *specular)
{
    *probability = 1.0;
    *specular = split->has_specular;
    if (!split->has_diffuse || !split->has_specular)
        return *specular ? &split->specular : &split->diffuse;
    double a_d = vec3_luminance(brdf_albedo(&split->diffuse, &h->frame, h->wi));
    double a_s = vec3_luminance(brdf_albedo(&split->specular, &h->frame, h->wi));
    if (!(a_d + a_s > 0))
        return NULL;
    double p_s = a_s / (a_d + a_s);
    *specular = rng_uniform(rng) < p_s;
    *probability = *specular ? p_s : 1.0 - p_s;
    return *specular ? &split->specular : &split->diffuse;
}

/* Russian roulette and the next direction (see the top of the file). Returns 0 when the
 * photon is absorbed; else updates *path and sets *ray to the scattered ray. by_parts:
 * trace_settings.by_parts. */
static int scatter(const struct photon_hit *h, int by_parts, struct rng *rng,
                   struct photon_path *path, struct ray *ray)
{
    double u[3];
    rng_uniforms(rng, u, 3);
    const struct material *through = h->material;
    double probability = 1.0;
    int specular = 0;
    struct brdf_split split;
    if (by_parts) {
        split = brdf_split(h->material);
        through = chosen_part(h, &split, rng, &probability, &specular);
        if (through == NULL)
            return 0;
    }
    struct brdf_sample bs;
    if (!brdf_sample(through, &h->frame, h->wi, u, &bs))
        return 0; /* black, or arrived below the shading normal */
    double adjoint = shading_share(&h->frame, h->ng, h->wi) /
                     shading_share(&h->frame, h->ng, bs.wi);
    if (!isfinite(adjoint))
        return 0; /* scattered along the geometric plane */
    bs.weight = vec3_scale(bs.weight, adjoint / probability);
    double q = fmin(1.0, vec3_max_component(bs.weight));
    if (!(rng_uniform(rng) < q))
        return 0; /* absorbed; also ends a zero or NaN weight */
    path->power = vec3_scale(vec3_mul(path->power, bs.weight), 1.0 / q); /* q > 0: u < q */
    if (!photon_power_fits(path->power))
        return 0; /* beyond the record's range: the departure at the top of the file */
    path->specular_only = path->specular_only && (by_parts ? specular : bs.delta);
    struct vec3 side = bs.transmitted ? vec3_neg(h->ng) : h->ng;
    *ray = make_ray(offset_origin(h->p, side), bs.wi);
    return 1;
}

/* Whether a photon whose path is specular_only so far can still be stored in a class
 * of store: later hits are caustic while the path stays specular, else indirect. Lets
 * a caustic map end a path at its first diffuse bounce. */
static int can_store_later(unsigned store, int specular_only)
{
    return (store & PHOTON_INDIRECT) || (specular_only && (store & PHOTON_CAUSTIC));
}

/* Follows photon i from its light until it is absorbed, leaves the scene or has made
 * max_depth bounces. -1 when the sink says stop. */
static int trace_photon(const struct scene *scene, const struct trace_settings *ts, size_t i,
                        const struct photon_sink *sink, unsigned long long *rays)
{
    struct rng rng = rng_stream(ts->seed, STREAM_PHOTON, ts->pass, i);
    struct photon_path path = {-1, {0, 0, 0}, 1, 0};
    path.batch = (unsigned)(i % PHOTON_BATCHES);
    struct ray ray;
    double u[6];
    rng_uniforms(&rng, u, 6);
    if (ts->projection != NULL) /* Sec. 3 (Jensen and Christensen 1994): stratified */
        u[0] = ((double)i + u[0]) / (double)ts->n_emit; /* i < N */
    if (!emit_photon(scene, ts, u, &ray, &path))
        return 0;
    for (int depth = 0;; depth++) {
        struct hit hit;
        (*rays)++;
        if (!scene_intersect(scene, ray, INFINITY, &hit))
            return 0;
        struct photon_hit h = photon_hit_at(scene, &hit, ray.dir);
        if (depth == 0 && (ts->store & PHOTON_SHADOW) &&
            store_shadow_photons(scene, ts, ray, &h, &path, sink, rays) < 0)
            return -1;
        unsigned kind = depth == 0 ? PHOTON_DIRECT
                                   : path.specular_only ? PHOTON_CAUSTIC : PHOTON_INDIRECT;
        struct vec3 stored = vec3_scale(path.power, shading_share(&h.frame, h.ng, h.wi));
        if ((ts->store & kind) && holds_photons(&h) && photon_power_fits(stored)) {
            struct photon_event e = photon_event_at(&h, stored, kind, &path);
            if (sink->store(sink->context, &e) < 0)
                return -1;
        }
        if (depth >= ts->max_depth || !scatter(&h, ts->by_parts, &rng, &path, &ray) ||
            !can_store_later(ts->store, path.specular_only))
            return 0;
    }
}

int trace_photons_into(const struct scene *scene, const struct trace_settings *ts,
                       const struct photon_sink *sink, unsigned long long *rays)
{
    assert(ts->n_emit <= MAX_PHOTONS && ts->max_depth >= 0);
    for (size_t i = 0; i < ts->n_emit; i++) {
        if (ts->watch != NULL && i > 0 && i % TRACE_WATCH_EVERY == 0)
            ts->watch->at(ts->watch->context, i);
        if (trace_photon(scene, ts, i, sink, rays) < 0)
            return -1;
    }
    return 0;
}

int trace_photons(const struct scene *scene, const struct trace_settings *ts,
                  struct photon_trace *out, struct error *err)
{
    assert(ts->max_stored >= 1 && ts->max_stored <= MAX_PHOTONS);
    memset(out, 0, sizeof *out);
    struct packing_sink packing = {out, ts->max_stored};
    struct photon_sink sink = {pack_photon, &packing};
    if (trace_photons_into(scene, ts, &sink, &out->rays) < 0) {
        photon_trace_free(out);
        return error_set(err, "", 0,
                         "photon map: more than %zu photons would be stored; emit fewer "
                         "photons or follow fewer bounces (--max-depth)",
                         ts->max_stored);
    }
    out->n_emitted = ts->n_emit;
    return 0;
}

void photon_trace_free(struct photon_trace *out)
{
    xfree(out->photons);
    memset(out, 0, sizeof *out);
}
