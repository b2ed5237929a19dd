/*
 * modes/jensen1996.c -- `--mode 1996`: Jensen 1996, "Global illumination using photon
 * maps", Sec. 3-5, in the paper's order.
 *
 * Pass 1 (Sec. 3) traces two photon maps: a caustic map of photons emitted towards the
 * specular objects and stored on diffuse surfaces after bounces through the specular part
 * f_r,s only (L S+ D, S "highly glossy and ideal specular": a glossy lobe as well as a
 * mirror; each photon bounce chooses its part, photon/trace.h),
 * and a global map of photons emitted towards everything and stored at every diffuse hit,
 * with shadow photons behind each first hit (Jensen and Christensen 1995; with
 * --no-shadow-rays, below); it lives in jensen1996_maps.c.
 *
 * Pass 2 (Sec. 4) is distribution ray tracing of Eq. 2,
 *   Lr = int f_r L_l cos + int f_r,s (L_c + L_d) cos + int f_r,d L_c cos + int f_r,d L_d cos,
 * the light split into direct (l), caustic (c: via f_r,s bounces only) and soft
 * indirect (d: reflected diffusely at least once), the BRDF into a diffuse and a specular
 * part (brdf_split(), scene/brdf.h). Where each term is evaluated accurately and where
 * approximately is Sec. 4's rule (accurate_or_approximate()); how:
 *   accurate     direct light by light sampling, with shadow rays only where the shadow
 *                photons nearby disagree (4.1); the specular part by Monte Carlo with
 *                BRDF importance sampling (4.2); caustics from the caustic map with the
 *                cone filter (4.3); soft indirect light by a final gather guided by the
 *                global map's photons, through Ward's irradiance cache on Lambertian
 *                surfaces (4.4);
 *   corner       (at the end of a short gather ray) as accurate, but with the soft
 *                indirect light the global map's estimate from its indirect photons (a
 *                departure, below; the paper's gathers, and its rays are approximate);
 *   through gloss (seen through a glossy lobe: a departure) direct light as accurate, the
 *                caustics and soft indirect light in one estimate from the global map's
 *                photons that are not direct;
 *   approximate  the global map's radiance estimate of the diffuse part, and still the
 *                specular part by Monte Carlo.
 *
 * Counting every path once. Direct light at accurate and corner points is light sampling
 * through the whole non-delta BRDF, so a ray sampled there by the specular part must not
 * add the emission it hits next; caustics at accurate points come from the caustic map,
 * so a gather ray must not add emission reached through f_r,s bounces either, nor the
 * direct light f_r,s reflects where it ends (direct_part()); and the
 * global estimate holds all light reflected by the diffuse part, so after an approximate
 * point only the specular part's rays continue, and what they hit counts in full. The
 * rule each ray carries (enum emission_rule) says which emission it may add. The sky is
 * a light like the others (scene/light.h), so a ray that leaves the scene follows the
 * same rule.
 *
 * Determinism. Every random number comes from the camera sample's stream (or, in the
 * cache's pre-pass, from rng_stream(seed, STREAM_CACHE, pixel, 0)). The irradiance cache
 * is filled by a pre-pass over the whole image in scanline order before the final pass,
 * which only reads it; where no record is usable the final pass gathers on the spot and
 * keeps nothing. So a pixel depends on nothing but the scene and the settings, and a crop
 * equals the same window of the whole image. Every crop repeats the maps and the cache;
 * --load-photons reads them from a file (photon/global_work.h) and remakes the records.
 *
 * Departures, each a switch whose --no-NAME (or value) is the paper's; --paper turns all
 * ten to the paper's side (src/modes/README.md: why, and what each measured):
 *   --precomputed-irradiance N  approximate Lambertian points, gather rays' ends among
 *       them, read irradiance precomputed at every N-th global photon (Christensen 1999),
 *       the pre-pass many times faster at the same error;
 *   --shadow-rays  every shadow ray is cast, among 13 objects cheaper than a 16-photon
 *       search (Sec. 4.1's shadow photons: --no-shadow-rays);
 *   --disc-coverage  a record divides its photons by the part of its disc a surface covers
 *       (photon/disc_coverage.h), not Eq. 3's pi r^2: past the floor's open front a disc
 *       darkens the balls' fronts, which see it;
 *   --both-lobes  glass at accurate points traces both its rays, as Whitted's;
 *   --glossy-corner  a surface seen through a glossy lobe is evaluated through gloss;
 *   --corner-photons  a corner's soft indirect light is the photons' (no gather in a gather);
 *   --exclude-rim-photon, --max-radius (caustics: --caustic-radius-fraction)  estimates;
 *   --bounded-reach, --gradient-limit  a cache record's R (photon/irradiance_cache.h).
 */
#include "jensen1996.h"

#include <stdio.h>
#include <string.h>
#include <time.h>

#include "../base/alloc.h"
#include "../photon/estimate.h"
#include "../photon/irradiance_cache.h"
#include "../photon/precomputed_irradiance.h"
#include "../scene/brdf.h"
#include "cache_pass.h"
#include "gather_plan.h"
#include "jensen1996_evaluation.h"
#include "jensen1996_maps.h"
#include "photons.h"
#include "specular_rays.h"
#include "surface.h"
#include "trace_progress.h"

/* ---- Sec. 4, pass 2: rendering ---- */

/* Which emission a ray may add where it lands (see the top of the file). */
enum emission_rule {
    EMISSION_COUNTED,     /* all of it: camera rays, and rays after approximate points  */
    EMISSION_SKIP_DIRECT, /* none at its first hit (light sampling had it); counted again
                             after a delta bounce (L S G: not sampled, not a caustic)   */
    EMISSION_SKIP_ALL     /* none through any chain of f_r,s bounces: a gather ray, whose
                             L S+ paths the caustic map holds                           */
};

struct path {
    struct vec3 beta;        /* throughput from the camera                               */
    int depth;               /* bounces so far                                           */
    enum evaluation eval;    /* how the surface it reaches is evaluated                  */
    enum emission_rule rule; /* which emission it may add                               */
    int branched;            /* whether it already branched into glossy_rays rays        */
};

/* A final gather's arrays, one entry per stratum. */
struct gather_scratch {
    double *importance;              /* photon flux times f_r,d                         */
    int *rays_in;                    /* rays allotted                                   */
    struct stratum_sample *strata;   /* what its rays found                             */
    struct vec3 *summand;            /* what strata_integral() sums: mean L
                                        (Lambertian), else mean f_r,d L                 */
};

/* The render's scratch and tallies: one per render, reached through the const mode. */
struct scratch {
    struct nearest *nn;              /* for every photon search                        */
    struct gather_scratch gathers[2]; /* [0] a gather's; [1] a corner's (corner_photons 0),
                                        made while the gather whose ray found the corner
                                        still needs its own                             */
    struct jensen1996_stats *stats;
};

struct jensen1996 {
    const struct scene *scene;
    const struct jensen1996_settings *settings;
    struct photon_maps maps;
    struct precomputed_irradiance *precomputed; /* owned; NULL with precomputed_irradiance 0 */
    struct irradiance_cache *cache; /* NULL with --cache-accuracy 0                     */
    int filling_cache;              /* the pre-pass: add records where none is usable  */
    struct estimate_settings global_es, caustic_es;
    double diagonal;                /* of the scene's box                               */
    struct gather_plan cached;      /* a gather that makes an irradiance record         */
    struct gather_plan per_sample;  /* a gather for one camera sample at a surface whose
                                       diffuse part is not Lambertian (no cache): the
                                       rays of one record shared among the --spp
                                       samples of a pixel, as distribution ray tracing
                                       spreads them                                     */
    int max_depth;
    struct scratch *scratch;
};

static struct vec3 trace(const struct jensen1996 *mode, struct ray ray, struct path path,
                         struct rng *rng, struct render_counters *counters);
static struct vec3 surface_radiance(const struct jensen1996 *mode, const struct surface *s,
                                    struct path path, struct rng *rng,
                                    struct render_counters *counters);

static struct vec3 emitted(const struct surface *s, enum emission_rule rule)
{
    return rule == EMISSION_COUNTED ? surface_emission(s) : vec3_zero();
}

/* Eq. 3 (Eq. 5 with the cone filter) through material at s. *r2 receives the squared
 * radius of the photons used. */
static struct vec3 photon_estimate(const struct jensen1996 *mode, const struct kdtree *map,
                                   const struct estimate_settings *es, const struct surface *s,
                                   const struct material *material,
                                   const struct shading_frame *frame, double *r2)
{
    struct estimate_point at;
    at.x = s->p;
    at.ng = s->ng;
    at.wo = s->wo;
    at.material = material;
    at.frame = frame;
    at.back = !s->front;
    struct vec3 l = radiance_estimate(map, &at, es, mode->scratch->nn);
    *r2 = mode->scratch->nn->r2;
    return l;
}

/* -- 4.1 direct illumination -- */

/* The BRDF that direct light is sampled through: the whole non-delta BRDF, except at the
 * end of a gather ray (rule EMISSION_SKIP_ALL), which takes only light reflected
 * diffusely (L_i,d, Sec. 4.4): the light f_r,s reflects there is L S D at the gathering
 * point, a caustic, which the caustic map holds. */
static const struct material *direct_part(const struct surface *s,
                                          const struct brdf_split *split, struct path path)
{
    return path.rule == EMISSION_SKIP_ALL ? &split->diffuse : s->material;
}

/* The first term of Eq. 2 at an accurate point: one sample of each light through the
 * whole non-delta BRDF; a shadow ray only where the shadow photons leave it open. */
static struct vec3 direct_illumination(const struct jensen1996 *mode, const struct surface *s,
                                       const struct material *through,
                                       const struct shading_frame *frame, struct rng *rng,
                                       struct render_counters *counters)
{
    struct jensen1996_stats *stats = mode->scratch->stats;
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < mode->scene->n_lights; i++) {
        struct light_sample ls;
        struct vec3 contribution;
        double u1 = rng_uniform(rng), u2 = rng_uniform(rng);
        if (!light_contribution(&mode->scene->lights[i], s, through, frame, u1, u2, &ls,
                                &contribution))
            continue;
        enum visibility v = UNDECIDED;
        if (mode->maps.visibility != NULL)
            v = shadow_photon_visibility(mode->maps.visibility[i], s, mode->global_es.max_r2,
                                         mode->scratch->nn);
        if (v != UNDECIDED) {
            stats->shadow_rays_avoided++;
        } else {
            stats->shadow_rays++;
            counters->rays++;
            v = light_blocked(mode->scene, s, &ls) ? OCCLUDED : VISIBLE;
        }
        if (v == VISIBLE)
            sum = vec3_add(sum, contribution);
    }
    return sum;
}

/* -- 4.2 specular reflection -- */

/* Follows one direction out of the specular part (specular_rays()' step): the path after
 * the bounce, its evaluation and emission rule; it has branched into glossy rays once it
 * had or this direction is one of several. */
static struct vec3 follow_specular(const struct specular_step *step,
                                   const struct brdf_sample *bs, double scale, int several)
{
    const struct jensen1996 *mode = step->mode;
    const struct path *path = step->path;
    struct path next;
    next.beta = vec3_mul(path->beta, bs->weight);
    next.depth = path->depth + 1;
    next.branched = path->branched || several;
    struct arrival bounce = {.last = SPECULAR_BOUNCE, .from = path->eval, .glossy = !bs->delta,
                             .weight = vec3_luminance(next.beta)};
    next.eval = accurate_or_approximate(mode->settings, &bounce);
    if (path->rule == EMISSION_SKIP_ALL)
        next.rule = EMISSION_SKIP_ALL; /* still on a gather ray's chain through f_r,s */
    else if (bs->delta)
        next.rule = EMISSION_COUNTED;
    else
        next.rule = path->eval == APPROXIMATE ? EMISSION_COUNTED : EMISSION_SKIP_DIRECT;
    next.beta = vec3_scale(next.beta, scale);
    return trace(mode, surface_ray(step->s, bs->wi, bs->transmitted), next, step->rng,
                 step->counters);
}

/* The second term of Eq. 2: Monte Carlo through the specular part, importance-sampled by
 * the BRDF, with Russian roulette (specular_rays(), which 1994 shares); glossy_rays rays
 * at the first accurate point of a path with a glossy lobe, else one (a path that
 * branched at every glossy hit of a sphere flake would grow exponentially). An ideal
 * specular surface evaluated accurately has nothing to sample: its reflected and
 * refracted rays are both followed, as in Whitted's ray tracer (1980), so a glass ball
 * seen directly shows no noise from choosing between them (both_lobes; off, the paper's
 * one sampled ray, as at approximate points). A lobe whose path weight falls below
 * --accurate-weight turns approximate and stops branching, which bounds the number of
 * rays. */
static struct vec3 specular_reflection(const struct jensen1996 *mode, const struct surface *s,
                                       const struct brdf_split *split,
                                       const struct shading_frame *frame, struct path path,
                                       struct rng *rng, struct render_counters *counters)
{
    if (path.depth >= mode->max_depth)
        return vec3_zero();
    int glossy = brdf_has_non_delta(&split->specular); /* a non-delta lobe */
    int n_rays =
        path.eval == ACCURATE && glossy && !path.branched ? mode->settings->glossy_rays : 1;
    struct specular_step step = {follow_specular, mode, &path, s, rng, counters};
    return specular_rays(&split->specular, frame,
                         path.eval == ACCURATE && mode->settings->both_lobes, n_rays,
                         path.beta, path.depth, &step);
}

/* -- 4.3 caustics -- */

/* The third term of Eq. 2: the caustic map's estimate through f_r,d, seen directly. */
static struct vec3 caustics(const struct jensen1996 *mode, const struct surface *s,
                            const struct brdf_split *split, const struct shading_frame *frame)
{
    const struct kdtree *map = mode->settings->one_map ? mode->maps.global : mode->maps.caustic;
    double r2;
    if (map == NULL)
        return vec3_zero();
    return photon_estimate(mode, map, &mode->caustic_es, s, &split->diffuse, frame, &r2);
}

/* -- 4.4 soft indirect illumination: the final gather -- */

/* The global map's radiance through the diffuse part at an approximate point, and *r2 its
 * disc: Eq. 3, or f_r,d times a record's irradiance (the departure from Sec. 4.4 above;
 * f_r,d towards the normal is rho / pi where it reflects towards wo at all). */
static struct vec3 global_estimate(const struct jensen1996 *mode, const struct surface *s,
                                   const struct brdf_split *split,
                                   const struct shading_frame *frame, double *r2)
{
    struct vec3 e;
    if (mode->precomputed != NULL && split->lambertian &&
        precomputed_irradiance_at(mode->precomputed, s->p, s->ng, mode->scratch->nn, &e, r2)) {
        mode->scratch->stats->precomputed_reads++;
        return vec3_mul(brdf_eval(&split->diffuse, frame, s->wo, frame->n), e);
    }
    mode->scratch->stats->global_estimates++;
    return photon_estimate(mode, mode->maps.global, &mode->global_es, s, &split->diffuse, frame,
                           r2);
}

/* At a surface seen through a glossy lobe (the departure in accurate_or_approximate()):
 * the caustics and the soft indirect light of Eq. 2 through f_r,d in one estimate, from
 * the global map's photons that are not direct, the blur of the lobe hiding the map's. */
static struct vec3 all_but_direct(const struct jensen1996 *mode, const struct surface *s,
                                  const struct brdf_split *split,
                                  const struct shading_frame *frame)
{
    struct estimate_settings es = mode->global_es;
    es.kinds = PHOTON_CAUSTIC | PHOTON_INDIRECT;
    double r2;
    return photon_estimate(mode, mode->maps.global, &es, s, &split->diffuse, frame, &r2);
}

/* Radiance arriving along a gather ray that hit s at distance d, evaluated as
 * accurate_or_approximate() says: in the corner way, or the global map's estimate. */
static struct vec3 gathered_radiance(const struct jensen1996 *mode, const struct surface *s,
                                     double d, struct path path, struct rng *rng,
                                     struct render_counters *counters)
{
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct brdf_split split = brdf_split(s->material);
    double r2 = 0.0;
    struct vec3 estimate = vec3_zero();
    if (split.has_diffuse)
        estimate = global_estimate(mode, s, &split, &frame, &r2);
    struct arrival bounce = {.last = DIFFUSE_BOUNCE, .from = path.eval, .length = d,
                             .radius2 = r2};
    path.eval = accurate_or_approximate(mode->settings, &bounce);
    if (path.eval == CORNER)
        return surface_radiance(mode, s, path, rng, counters);
    struct vec3 l = vec3_add(emitted(s, path.rule), estimate);
    if (split.has_specular)
        l = vec3_add(l, specular_reflection(mode, s, &split, &frame, path, rng, counters));
    return l;
}

/* Jensen 1995's importance from the photon map on Ward and Heckbert's strata: the flux of
 * the nearest global photons arriving through each stratum, times f_r,d there, into
 * importance[]; returns their sum. */
static double stratum_importance(const struct jensen1996 *mode, const struct gather_plan *plan,
                                 const struct surface *s, const struct material *diffuse,
                                 const struct shading_frame *frame, double *importance)
{
    int mn = plan->theta * plan->phi;
    for (int i = 0; i < mn; i++)
        importance[i] = 0.0;
    struct nearest *nn = mode->scratch->nn;
    locate_photons(mode->maps.global, s->p, mode->global_es.max_r2, mode->global_es.k, nn);
    double total = 0.0;
    for (size_t i = 0; i < nn->found; i++) {
        struct vec3 wi = photon_direction(nn->photon[i]);
        if (!(vec3_dot(wi, s->ng) > 0) || !(vec3_dot(wi, frame->n) > 0))
            continue;
        struct vec3 local = vec3(vec3_dot(wi, frame->t), vec3_dot(wi, frame->b),
                                 vec3_dot(wi, frame->n));
        int j, k;
        stratum_of(plan->theta, plan->phi, local, &j, &k);
        double w = vec3_luminance(vec3_mul(photon_power(nn->photon[i]),
                                           brdf_eval(diffuse, frame, s->wo, wi)));
        importance[j * plan->phi + k] += w;
        total += w;
    }
    return total;
}

/* The final gather at s: the strata's mean radiances and distances, and the summands of
 * its estimate (the mean radiances, or for a part that is not Lambertian mean f_r,d L),
 * in the scratch it returns. */
static const struct gather_scratch *final_gather(const struct jensen1996 *mode,
                                                 const struct gather_plan *plan,
                                                 const struct surface *s,
                                                 const struct material *diffuse,
                                                 int lambertian,
                                                 const struct shading_frame *frame,
                                                 struct path path, struct rng *rng,
                                                 struct render_counters *counters)
{
    struct scratch *st = mode->scratch;
    struct gather_scratch *sc = &st->gathers[path.eval == CORNER]; /* inside a gather */
    allot_rays(plan, stratum_importance(mode, plan, s, diffuse, frame, sc->importance),
               sc->importance, sc->rays_in);
    struct path gather = path;
    gather.depth = path.depth + 1;
    gather.rule = EMISSION_SKIP_ALL;
    st->stats->gathers++;
    for (int j = 0; j < plan->theta; j++) {
        for (int k = 0; k < plan->phi; k++) {
            int i = j * plan->phi + k;
            struct vec3 sum = vec3_zero(), reflected = vec3_zero();
            double nearest = INFINITY;
            for (int r = 0; r < sc->rays_in[i]; r++) {
                struct vec3 wi;
                if (!gather_direction(frame, s->ng, plan->theta, plan->phi, j, k, rng, &wi))
                    continue; /* below the geometric surface: no light arrives */
                struct hit hit;
                counters->rays++;
                st->stats->gather_rays++;
                struct vec3 li = vec3_zero(); /* the sky: direct light, sampled */
                if (scene_intersect(mode->scene, surface_ray(s, wi, 0), INFINITY, &hit)) {
                    struct surface at = surface_at(mode->scene, &hit, vec3_neg(wi));
                    li = gathered_radiance(mode, &at, hit.t, gather, rng, counters);
                    nearest = fmin(nearest, hit.t);
                }
                sum = vec3_add(sum, li);
                if (!lambertian)
                    reflected = vec3_add(reflected, vec3_mul(brdf_eval(diffuse, frame, s->wo,
                                                                       wi), li));
            }
            sc->strata[i].radiance = vec3_scale(sum, 1.0 / sc->rays_in[i]);
            sc->strata[i].distance = nearest;
            sc->summand[i] = lambertian ? sc->strata[i].radiance
                                        : vec3_scale(reflected, 1.0 / sc->rays_in[i]);
        }
    }
    return sc;
}

/* Irradiance at s from a final gather, as an irradiance record. */
static struct irradiance_record gathered_record(const struct jensen1996 *mode,
                                                const struct surface *s,
                                                const struct material *diffuse,
                                                const struct shading_frame *frame,
                                                struct path path, struct rng *rng,
                                                struct render_counters *counters)
{
    const struct gather_scratch *sc =
        final_gather(mode, &mode->cached, s, diffuse, 1, frame, path, rng, counters);
    /* no cache: R is unused */
    double a = mode->cache != NULL ? mode->settings->cache_accuracy : 1.0;
    struct record_reach reach = record_reach_at(&mode->scene->camera, s->p, frame->n, a,
                                                mode->diagonal, mode->settings->bounded_reach,
                                                mode->settings->gradient_limit);
    return irradiance_record_of(s->p, frame->t, frame->b, frame->n, mode->cached.theta,
                                mode->cached.phi, sc->strata, reach);
}

/* The fourth term of Eq. 2 at an accurate point. Lambertian: rho / pi times the
 * irradiance (diffuse_reflection(): none, and no gather, where wo lies below the shading
 * normal), interpolated from the cache where a record is usable (Ward 1988), else
 * gathered: in the pre-pass into a new record, without a cache as one too; in the final
 * pass (a point no record covers, seen through glass or a curved mirror, say) with the
 * camera sample's share of the rays, kept nowhere. Not Lambertian: no cache can hold
 * it (it depends on wo), so each camera sample gathers its share, the mean f_r,d L per
 * stratum. */
static struct vec3 soft_indirect(const struct jensen1996 *mode, const struct surface *s,
                                 const struct brdf_split *split,
                                 const struct shading_frame *frame, struct path path,
                                 struct rng *rng, struct render_counters *counters)
{
    if (!split->lambertian)
        return strata_integral(&mode->per_sample,
                               final_gather(mode, &mode->per_sample, s, &split->diffuse, 0,
                                            frame, path, rng, counters)->summand);
    if (vec3_max_component(brdf_albedo(&split->diffuse, frame, s->wo)) <= 0)
        return vec3_zero();
    struct vec3 e;
    /* The pre-pass asks with a stricter a than the final pass reads with, so that the
     * final pass's camera samples find the records made at pixel centres. */
    double a =
        mode->settings->cache_accuracy * (mode->filling_cache ? CACHE_FILL_STRICTNESS : 1.0);
    if (mode->cache != NULL && irradiance_cache_lookup(mode->cache, s->p, frame->n, a, &e))
        return diffuse_reflection(s, &split->diffuse, frame, e);
    if (mode->cache == NULL || mode->filling_cache) {
        struct irradiance_record record =
            gathered_record(mode, s, &split->diffuse, frame, path, rng, counters);
        if (mode->cache != NULL)
            irradiance_cache_add(mode->cache, &record);
        e = record.e;
    } else {
        mode->scratch->stats->gather_fallbacks++;
        e = strata_integral(&mode->per_sample,
                            final_gather(mode, &mode->per_sample, s, &split->diffuse, 1, frame,
                                         path, rng, counters)->summand);
    }
    return diffuse_reflection(s, &split->diffuse, frame, e);
}

/* -- a surface, term by term -- */

/* Radiance leaving s towards s->wo, Eq. 2 evaluated as path.eval says. */
static struct vec3 surface_radiance(const struct jensen1996 *mode, const struct surface *s,
                                    struct path path, struct rng *rng,
                                    struct render_counters *counters)
{
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct brdf_split split = brdf_split(s->material);
    struct vec3 l = emitted(s, path.rule);
    double r2;
    if (path.eval == APPROXIMATE) {
        if (split.has_diffuse)
            l = vec3_add(l, global_estimate(mode, s, &split, &frame, &r2));
    } else {
        if (brdf_has_non_delta(s->material))
            l = vec3_add(l, direct_illumination(mode, s, direct_part(s, &split, path), &frame,
                                                rng, counters));
        if (split.has_diffuse && path.eval == THROUGH_GLOSS) {
            l = vec3_add(l, all_but_direct(mode, s, &split, &frame));
        } else if (split.has_diffuse) {
            l = vec3_add(l, caustics(mode, s, &split, &frame));
            if (gathers_soft_indirect(mode->settings, path.eval)) {
                l = vec3_add(l, soft_indirect(mode, s, &split, &frame, path, rng, counters));
            } else { /* a corner's, the photons' (the departure in gathers_soft_indirect()) */
                struct estimate_settings indirect = mode->global_es;
                indirect.kinds = PHOTON_INDIRECT;
                l = vec3_add(l, photon_estimate(mode, mode->maps.global, &indirect, s,
                                                &split.diffuse, &frame, &r2));
            }
        }
    }
    if (split.has_specular)
        l = vec3_add(l, specular_reflection(mode, s, &split, &frame, path, rng, counters));
    return l;
}

static struct vec3 trace(const struct jensen1996 *mode, struct ray ray, struct path path,
                         struct rng *rng, struct render_counters *counters)
{
    struct surface s;
    double t;
    if (!ray_surface(mode->scene, ray, counters, &s, &t)) /* the sky, emission as any other */
        return path.rule == EMISSION_COUNTED ? mode->scene->background : vec3_zero();
    return surface_radiance(mode, &s, path, rng, counters);
}

static struct path camera_path(const struct jensen1996 *mode)
{
    struct arrival from_eye = {.last = FROM_EYE};
    struct path path = {vec3(1.0, 1.0, 1.0), 0,
                        accurate_or_approximate(mode->settings, &from_eye), EMISSION_COUNTED,
                        0};
    return path;
}

static struct vec3 camera_ray_radiance(const void *mode, struct ray ray,
                                       const struct first_bounce *first, struct rng *rng,
                                       struct render_counters *counters)
{
    (void)first; /* its first bounce draws from the stream */
    return trace(mode, ray, camera_path(mode), rng, counters);
}

/* ---- putting it together ---- */

/* A checkpoint that adds the photon pass's and the pre-pass's seconds to the render's,
 * and counts work as photons emitted plus gather rays so far. */
struct pass2_checkpoint {
    const struct checkpoint *inner;      /* borrowed */
    double seconds;                      /* added to every checkpoint's time */
    const struct jensen1996_stats *stats; /* borrowed */
};

static double pass2_checkpoint_at(void *context, const struct image *mean, long long work,
                                double seconds)
{
    const struct pass2_checkpoint *jc = context;
    (void)work;
    long long spent = (long long)jc->stats->photons_emitted + (long long)jc->stats->gather_rays;
    return jc->inner->at(jc->inner->context, mean, spent, seconds + jc->seconds);
}

static struct scratch *scratch_create(const struct jensen1996 *mode,
                                      struct jensen1996_stats *stats)
{
    size_t k = mode->settings->global_gather > mode->settings->caustic_gather
                   ? mode->settings->global_gather
                   : mode->settings->caustic_gather;
    k = k > J96_VISIBILITY_PHOTONS ? k : J96_VISIBILITY_PHOTONS;
    size_t mn = (size_t)mode->cached.theta * (size_t)mode->cached.phi; /* the larger plan */
    struct scratch *sc = xmalloc(1, sizeof *sc, "render scratch");
    sc->nn = nearest_create(k);
    for (int i = 0; i < 2; i++) {
        struct gather_scratch *g = &sc->gathers[i];
        g->importance = xmalloc(mn, sizeof *g->importance, "strata");
        g->rays_in = xmalloc(mn, sizeof *g->rays_in, "strata");
        g->strata = xmalloc(mn, sizeof *g->strata, "strata");
        g->summand = xmalloc(mn, sizeof *g->summand, "strata");
    }
    sc->stats = stats;
    return sc;
}

static void scratch_free(struct scratch *sc)
{
    nearest_free(sc->nn);
    for (int i = 0; i < 2; i++) {
        xfree(sc->gathers[i].importance);
        xfree(sc->gathers[i].rays_in);
        xfree(sc->gathers[i].strata);
        xfree(sc->gathers[i].summand);
    }
    xfree(sc);
}

/* The mode's settings from the scene and the user's. */
static void set_up(struct jensen1996 *mode, const struct scene *scene,
                   const struct render_settings *rs, const struct jensen1996_settings *settings,
                   struct jensen1996_stats *stats)
{
    struct aabb box = geometry_bounds(scene->geometry);
    mode->scene = scene;
    mode->settings = settings;
    mode->diagonal = scene_diagonal(scene);
    struct max_radii radii =
        max_radii_of(settings->max_radius, settings->caustic_radius_fraction, mode->diagonal);
    mode->global_es.k = settings->global_gather;
    mode->global_es.max_r2 = radii.all_r2;
    mode->global_es.cone_k = 0;
    mode->global_es.kinds = 0;
    mode->global_es.exclude_rim = settings->exclude_rim;
    mode->caustic_es.k = settings->caustic_gather;
    mode->caustic_es.max_r2 = radii.caustic_r2;
    mode->caustic_es.cone_k = settings->cone_k;
    mode->caustic_es.kinds = settings->one_map ? PHOTON_CAUSTIC : 0;
    mode->caustic_es.exclude_rim = settings->exclude_rim;
    mode->cached = gather_plan_of(settings->gather_rays);
    mode->per_sample = gather_plan_of(settings->gather_rays / rs->spp);
    mode->max_depth = rs->max_depth;
    mode->filling_cache = 0;
    mode->cache = NULL;
    if (settings->cache_accuracy > 0 && isfinite(box.lo.x))
        mode->cache = irradiance_cache_create(box, settings->cache_accuracy);
    mode->precomputed = NULL;
    if (mode->maps.records != NULL) {
        struct irradiance_settings is = {mode->global_es.k, mode->global_es.max_r2, 0, 0,
                                         settings->exclude_rim};
        mode->precomputed = precompute_watched(mode->maps.global, mode->maps.records, &is,
                                               settings->disc_coverage ? scene : NULL,
                                               rs->progress, &stats->seconds_precompute);
        stats->bytes_precomputed += precomputed_irradiance_bytes(mode->precomputed);
    }
}

struct render_result render_jensen1996(const struct scene *scene,
                                       const struct render_settings *rs,
                                       const struct jensen1996_settings *settings,
                                       int want_variance, struct render_counters *counters,
                                       struct jensen1996_stats *stats, struct error *err)
{
    struct render_result result = {NULL, NULL, NULL, NULL, NULL, NULL, 0.0};
    memset(stats, 0, sizeof *stats);
    struct jensen1996 mode;
    memset(&mode, 0, sizeof mode);
    struct global_work own_work = {NULL, 0, NULL, 0, NULL}; /* without settings->work */
    struct jensen1996_settings with_work = *settings;
    if (with_work.work == NULL)
        with_work.work = &own_work;
    settings = &with_work;
    int loaded = settings->work->n_maps > 0;
    clock_t start = clock();
    if ((!loaded && build_photon_maps(scene, rs, settings, stats, err) < 0) ||
        borrow_photon_maps(scene, settings, &mode.maps, stats, err) < 0) {
        global_work_free(&own_work);
        return result;
    }
    set_up(&mode, scene, rs, settings, stats);
    stats->seconds_photons = cpu_seconds(start);
    stats->strata_theta = mode.cached.theta;
    stats->strata_phi = mode.cached.phi;
    mode.scratch = scratch_create(&mode, stats);
    start = clock();
    if (mode.cache != NULL && loaded) {
        global_work_fill_cache(settings->work, mode.cache);
    } else if (mode.cache != NULL) {
        struct radiance_estimator filler = {camera_ray_radiance, &mode, NULL};
        mode.filling_cache = 1;
        fill_cache_pass(scene, rs->seed, filler, mode.cache, rs->progress, counters);
        mode.filling_cache = 0;
        global_work_keep_cache(settings->work, mode.cache);
    }
    stats->seconds_cache = cpu_seconds(start);
    stats->cache_records = mode.cache != NULL ? irradiance_cache_records(mode.cache) : 0;
    stats->bytes_cache = mode.cache != NULL ? irradiance_cache_bytes(mode.cache) : 0;
    struct radiance_estimator estimator = {camera_ray_radiance, &mode, NULL};
    double before = stats->seconds_photons + stats->seconds_cache;
    struct pass2_checkpoint jc = {settings->report, before, stats};
    struct checkpoint report = {pass2_checkpoint_at, &jc};
    result = render_pixels(scene, rs, estimator, want_variance,
                           settings->report != NULL ? &report : NULL, counters);
    stats->seconds_final_pass = result.seconds;
    result.seconds += before;
    scratch_free(mode.scratch);
    irradiance_cache_free(mode.cache);
    precomputed_irradiance_free(mode.precomputed);
    global_work_free(&own_work); /* mode.maps borrowed from it */
    return result;
}
