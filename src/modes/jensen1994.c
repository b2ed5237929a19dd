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
 * since the light, glossy lobes among them: each bounce chooses f_r,s or f_r,d) or not
 * (DP); with --irradiance-store illumination, a deposit on a
 * quad or sphere goes to its illumination maps instead (Sec. 3.2: DI, and CI sub-maps
 * where caustics land, photon/illumination_map.h).
 *
 * Pass 2 (Sec. 4), Monte Carlo ray tracing of
 *   L_p = L_e + L_r,   L_r = L_r,s + L_r,d,   L_r,d = L_r,d,l + L_r,d,s + L_r,d,d,
 * with the BRDF split into a specular-like part f_r,s (mirror, glass, glossy lobes:
 * highly directional) and a diffuse-like part f_r,d (brdf_split(), scene/brdf.h):
 *   L_r,s    recursive ray tracing of f_r,s: every lobe of a mirror or glass (a
 *            departure, below), one ray sampled from a glossy lobe;
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
 * for a Lambertian part, the paper's only diffuse-like kind (Sec. 5: "specular, rough
 * specular and lambertian"). A part that is not gathers at each camera sample instead, as
 * Sec. 4.0.3 treats "surfaces with complex BRDF's" (eye_radiance()), and reads its photons
 * by their direction, which the paper does not specify (stored_reflection()).
 *
 * Departures, each a switch that --paper turns to the paper's side (src/modes/README.md:
 * why, and what each measured):
 *   --both-lobes  L_r,s follows both of glass's lobes, as Whitted's ray tracer does (the
 *       paper's recursive Monte Carlo: one, chosen by the BRDF's sampling);
 *   --glossy-photons  a surface seen through a glossy lobe reads the photon map, as a
 *       gather ray's end does (the paper's: evaluated in full, with its own gather);
 *   --lobe-lights  area lights and the sky are sampled through a glossy lobe too, weighted
 *       against the lobe's ray by the power heuristic (the paper's: the ray alone);
 *   --exclude-rim-photon  an estimate leaves its rim photon out (photon/estimate.h);
 *   --max-radius  an estimate stops at a tenth of the scene's diagonal, a caustic one at a
 *       quarter of that (--caustic-radius-fraction), where the paper's sphere grows until
 *       it holds its photons (--no-max-radius);
 *   --bounded-reach, --gradient-limit  a cache record's R (photon/irradiance_cache.h);
 *   --specular-spp  a pixel that sees a light through mirrors or glass takes 64 x --spp
 *       samples (--paper: --spp, as every pixel).
 * --paper leaves --adaptive off: the paper sampled
 * adaptively (Sec. 5), by a rule and threshold not specified by the paper. The departures
 * without a switch (the CP photons' own tree, the cache's pre-pass, point lights sampled
 * through a glossy lobe) are listed in src/modes/README.md.
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
#include "../photon/precomputed_irradiance.h"
#include "../photon/projection_map.h"
#include "../photon/trace.h"
#include "cache_pass.h"
#include "gather_plan.h"
#include "jensen1994_maps.h"
#include "photons.h"
#include "specular_rays.h"
#include "surface.h"
#include "trace_progress.h"

/* ---- Sec. 4, pass 2: Monte Carlo ray tracing ---- */

/* Where the last bounce left from, when it was a glossy lobe's ray whose lights were
 * also sampled through that lobe (lights_through_lobe()): the emission it finds is
 * weighted against those samples. */
struct lobe_origin {
    int weighted;     /* 1: the last bounce sampled lights through its lobe too          */
    struct vec3 p, n; /* the point it left and its shading normal                        */
    double pdf;       /* solid-angle pdf of the lobe's direction                         */
};

/* A path from the eye, or from a gather (whose surfaces read the irradiance stores). */
struct path {
    struct vec3 beta; /* throughput since the eye or the gathering point                */
    int depth;        /* bounces so far                                                  */
    int secondary;    /* 1: surfaces read the photon map (a gather ray, or with
                         glossy_photons a path through a glossy lobe) instead of gathering */
    int emission;     /* 1: it adds the emission it reaches (the eye's rays; a gather
                         ray's light through f_r,s is CP's)                               */
    struct lobe_origin lobe; /* NO_LOBE but right after a glossy bounce from the eye    */
};
#define NO_LOBE {0, {0, 0, 0}, {0, 0, 0}, 0.0}

struct jensen1994 {
    const struct scene *scene;
    const struct jensen1994_settings *settings;
    struct irradiance_stores stores;
    struct irradiance_settings all_photons, caustic_photons;
    struct kdtree *records;          /* owned: every N-th photon of the map; NULL without */
    struct precomputed_irradiance *precomputed; /* owned: the all-photons estimate at each
                                                   record; NULL without                  */
    struct irradiance_cache *cache;
    int filling_cache;               /* the pre-pass: records where none is usable      */
    int strata_theta, strata_phi;    /* a record's m x n strata, one ray each            */
    int sample_theta, sample_phi;    /* a camera sample's share of them, for a glossy
                                        part's gather (sample_gather())                  */
    int light_strata;                /* each light sampled on light_strata^2 strata      */
    double diagonal;                 /* of the scene's box                               */
    int max_depth;                   /* longest chain of bounces followed                */
    struct nearest *nn;              /* scratch for every photon search                  */
    struct stratum_sample *strata;   /* scratch of a gather                              */
    struct jensen1994_stats *stats;
};

static struct vec3 trace(const struct jensen1994 *mode, struct ray ray, struct path path,
                         struct rng *rng, struct render_counters *counters);
static struct vec3 trace_from(const struct jensen1994 *mode, const struct surface *s,
                              struct path path, struct rng *rng,
                              struct render_counters *counters);

/* -- 4.0.1 L_r,d,l: direct light -- */

/* The k of the k x k strata add_light_samples() samples a light on: a point light, whose
 * every sample is the same, 1. */
static int light_strata_of(const struct jensen1994 *mode, const struct light *light)
{
    return light->kind == LIGHT_POINT ? 1 : mode->light_strata;
}

/* Light `light` sampled on a k x k grid of jittered strata of its sample space, through
 * `part`, with a shadow ray per sample. Adds the samples' mean to *sum, each weighted by
 * the power heuristic against the ray a glossy lobe `lobe` samples (NULL: weight 1). */
static void add_light_samples(const struct jensen1994 *mode, const struct light *light,
                              const struct surface *s, const struct material *part,
                              const struct material *lobe, const struct shading_frame *frame,
                              struct rng *rng, struct render_counters *counters,
                              struct vec3 *sum)
{
    int k = light_strata_of(mode, light), n = k * k;
    for (int j = 0; j < n; j++) {
        double u1 = (j % k + rng_uniform(rng)) / k, u2 = (j / k + rng_uniform(rng)) / k;
        struct light_sample ls;
        struct vec3 contribution;
        if (!light_contribution(light, s, part, frame, u1, u2, &ls, &contribution))
            continue;
        mode->stats->shadow_rays++;
        counters->rays++;
        if (light_blocked(mode->scene, s, &ls))
            continue;
        double w = lobe == NULL ? 1.0
                                : power_heuristic(n * ls.pdf,
                                                  brdf_pdf(lobe, frame, s->wo, ls.wi));
        *sum = vec3_add(*sum, vec3_scale(contribution, w / n));
    }
}

/* L_r,d,l: every light's stratified samples through the diffuse-like part. */
static struct vec3 direct_light(const struct jensen1994 *mode, const struct surface *s,
                                const struct material *diffuse,
                                const struct shading_frame *frame, struct rng *rng,
                                struct render_counters *counters)
{
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < mode->scene->n_lights; i++)
        add_light_samples(mode, &mode->scene->lights[i], s, diffuse, NULL, frame, rng, counters,
                          &sum);
    return sum;
}

/* L_r,s is traced, and a traced ray never meets a point light, a delta, so a glossy
 * lobe's highlight of one would be lost (the sphere flake's Phong spheres would be dark:
 * src/modes/README.md); a departure without a switch samples the point lights through
 * the glossy lobe too. Another, with lobe_lights (off: the paper's), samples every other
 * light through it, each sample weighted by the power heuristic against the lobe's own
 * ray, which finds the same light weighted the other way (emission_found()): a small
 * light seen through a broad lobe is found by its samples, where the lobe's ray alone
 * meets it rarely and brightly. */
static struct vec3 lights_through_lobe(const struct jensen1994 *mode, const struct surface *s,
                                       const struct material *glossy,
                                       const struct shading_frame *frame, struct rng *rng,
                                       struct render_counters *counters)
{
    struct vec3 sum = vec3_zero();
    for (size_t i = 0; i < mode->scene->n_lights; i++) {
        const struct light *light = &mode->scene->lights[i];
        if (light->kind == LIGHT_POINT)
            add_light_samples(mode, light, s, glossy, NULL, frame, rng, counters, &sum);
        else if (mode->settings->lobe_lights)
            add_light_samples(mode, light, s, glossy, glossy, frame, rng, counters, &sum);
    }
    return sum;
}

/* Emission le of light `light` (-1: none), found at q along unit wi by the ray of the
 * path's last bounce: weighted against the light's samples through that bounce's lobe
 * when it took them (lights_through_lobe()), else all of it. */
static struct vec3 emission_found(const struct jensen1994 *mode, int light, struct vec3 le,
                                  struct vec3 q, struct vec3 wi, const struct path *path)
{
    if (!path->lobe.weighted || light < 0 || vec3_max_component(le) <= 0)
        return le;
    const struct light *l = &mode->scene->lights[light];
    int k = light_strata_of(mode, l);
    double pdf_light = k * k * light_pdf(l, path->lobe.p, path->lobe.n, q, wi);
    return vec3_scale(le, power_heuristic(path->lobe.pdf, pdf_light));
}

/* The emission a path finds at s. */
static struct vec3 surface_emission_found(const struct jensen1994 *mode,
                                          const struct surface *s, const struct path *path)
{
    return emission_found(mode, mode->scene->light_of_prim[s->prim], surface_emission(s), s->p,
                          vec3_neg(s->wo), path);
}

/* The radiance the diffuse-like part reflects from the photons of estimate `is`, read
 * from its records where there are some (NULL: none): albedo / pi times their
 * irradiance (Sec. 4.0.2-4.0.3: the paper's diffuse-like surfaces are Lambertian).
 * Where the photons kept their direction (keeps_direction()), on a part that is not
 * Lambertian, the reflected light depends on where it came from, so it is the 1996
 * paper's Eq. 3 through f_r,d (no differential checking): how photons are read there is
 * not specified by the paper, whose photons keep a normal, no direction. */
static struct vec3 stored_reflection(const struct jensen1994 *mode, const struct surface *s,
                                     const struct material *diffuse,
                                     const struct shading_frame *frame,
                                     const struct irradiance_settings *is,
                                     const struct precomputed_irradiance *records)
{
    if (keeps_direction(mode->stores.illumination, s->material, s->prim)) {
        struct estimate_point at = {s->p, s->ng, s->wo, diffuse, frame, !s->front};
        struct estimate_settings es = {is->n, is->max_r2, 0.0, is->kinds, is->exclude_rim};
        return radiance_estimate(mode->stores.glossy, &at, &es, mode->nn);
    }
    struct store_query q = {s->p, s->ng, s->prim, s->u, s->v, is, records};
    return diffuse_reflection(s, diffuse, frame,
                              stored_irradiance(&mode->stores, &q, mode->nn));
}

/* -- 4.0.2 L_r,d,s: caustics, from the CP photons alone -- */

static struct vec3 caustic_light(const struct jensen1994 *mode, const struct surface *s,
                                 const struct material *diffuse,
                                 const struct shading_frame *frame)
{
    return stored_reflection(mode, s, diffuse, frame, &mode->caustic_photons, NULL);
}

/* -- L_r,s: the specular-like part by recursive Monte Carlo ray tracing -- */

/* The path after a bounce off lobe bs of f_r,s. A glossy lobe is as specular as a mirror
 * here: the light it brings from a light source is a caustic, which CP photons hold (each
 * photon bounce chooses f_r,s or f_r,d, photon/trace.h), so a gather ray still adds no
 * emission after one; the eye's rays add all they reach. Departs from Sec. 4's recursion
 * at a glossy bounce (glossy_photons; off, the paper's: every surface seen from the eye
 * is evaluated in full): a surface seen through a glossy lobe, whose blur hides the photon map's, reads
 * the photon map as a gather ray's end does, instead of a final gather for every ray of
 * every glossy bounce (on the sphere flake, whose Phong spheres see each other, half the
 * camera samples fell outside the cache's records and gathered on the spot). */
static struct path after_bounce(const struct jensen1994 *mode, const struct surface *s,
                                const struct brdf_sample *bs, struct path path)
{
    path.depth++;
    /* on a path from the eye, lights_through_lobe() sampled the lights through this lobe */
    path.lobe.weighted = !bs->delta && !path.secondary && mode->settings->lobe_lights;
    path.lobe.p = s->p;
    path.lobe.n = s->ns;
    path.lobe.pdf = bs->pdf;
    if (!bs->delta)
        path.secondary = path.secondary || mode->settings->glossy_photons;
    return path;
}

/* The radiance arriving along lobe bs of f_r,s (specular_rays()' step): the path after
 * the bounce, its throughput scaled as specular_rays.h says. 1994 samples one ray at a
 * time, so `several` is always 0. */
static struct vec3 follow_lobe(const struct specular_step *step, const struct brdf_sample *bs,
                               double scale, int several)
{
    const struct jensen1994 *mode = step->mode;
    struct path path = *(const struct path *)step->path;
    (void)several;
    path.beta = vec3_scale(vec3_mul(path.beta, bs->weight), scale);
    path = after_bounce(mode, step->s, bs, path);
    return trace(mode, surface_ray(step->s, bs->wi, bs->transmitted), path, step->rng,
                 step->counters);
}

/* Recursive ray tracing of f_r,s: an ideal mirror's or glass's every lobe (reflection and
 * refraction both, as Whitted's ray tracer, so glass shows no noise from choosing
 * between them; with both_lobes off, the paper's Monte Carlo: one lobe, chosen by the
 * BRDF's sampling), else one direction sampled from the glossy lobe; Russian roulette
 * after ROULETTE_DEPTH bounces (specular_rays(), which 1996 shares). */
static struct vec3 specular_light(const struct jensen1994 *mode, const struct surface *s,
                                  const struct material *specular,
                                  const struct shading_frame *frame, struct path path,
                                  struct rng *rng, struct render_counters *counters)
{
    if (path.depth >= mode->max_depth)
        return vec3_zero();
    struct specular_step step = {follow_lobe, mode, &path, s, rng, counters};
    return specular_rays(specular, frame, mode->settings->both_lobes, 1, path.beta,
                         path.depth, &step);
}

/* -- 4.0.3 L_r,d,d: multiple diffuse reflections by irradiance gradients -- */

/* The ray of stratum (j, k) of an n_theta x n_phi gather at s (cosine-distributed within
 * it): the radiance the secondary path finds (the irradiance stores where it lands) and
 * the distance to its first surface, or zero and infinity when it leaves the scene (the
 * sky is direct light, which direct_light() samples) or starts below the surface. */
static struct stratum_sample gather_stratum(const struct jensen1994 *mode,
                                            const struct surface *s,
                                            const struct shading_frame *frame, int n_theta,
                                            int n_phi, int j, int k, struct path gather,
                                            struct vec3 *wi, struct rng *rng,
                                            struct render_counters *counters)
{
    struct stratum_sample sample = {{0.0, 0.0, 0.0}, INFINITY};
    if (!gather_direction(frame, s->ng, n_theta, n_phi, j, k, rng, wi))
        return sample; /* below the geometric surface: no light arrives */
    struct surface at;
    double t;
    mode->stats->gradient_rays++;
    if (!ray_surface(mode->scene, surface_ray(s, *wi, 0), counters, &at, &t))
        return sample;
    sample.radiance = trace_from(mode, &at, gather, rng, counters);
    sample.distance = t;
    return sample;
}

/* Ward and Heckbert's gather at s: one cosine-distributed ray per stratum. Fills
 * mode->strata; returns the record with its radius bounded as cache_pass.h says. */
static struct irradiance_record gather_record(const struct jensen1994 *mode,
                                              const struct surface *s,
                                              const struct shading_frame *frame,
                                              struct path path, struct rng *rng,
                                              struct render_counters *counters)
{
    struct path gather = {vec3(1, 1, 1), path.depth + 1, 1, 0, NO_LOBE};
    for (int j = 0; j < mode->strata_theta; j++)
        for (int k = 0; k < mode->strata_phi; k++) {
            struct vec3 wi;
            mode->strata[j * mode->strata_phi + k] =
                gather_stratum(mode, s, frame, mode->strata_theta, mode->strata_phi, j, k,
                               gather, &wi, rng, counters);
        }
    struct record_reach reach = record_reach_at(
        &mode->scene->camera, s->p, frame->n, mode->settings->cache_accuracy, mode->diagonal,
        mode->settings->bounded_reach, mode->settings->gradient_limit);
    return irradiance_record_of(s->p, frame->t, frame->b, frame->n, mode->strata_theta,
                                mode->strata_phi, mode->strata, reach);
}

/* A camera sample's share of a record's gather at s, sample_theta x sample_phi strata of
 * one ray each: pi / (m n) times the sum over them of w L, w = f_r,d(wi, wo) through
 * `through` (the reflected radiance), or 1 for NULL (the irradiance). Its mean over a
 * pixel's samples is the pixel's, with the cost of one record per pixel. */
static struct vec3 sample_gather(const struct jensen1994 *mode, const struct surface *s,
                                 const struct material *through,
                                 const struct shading_frame *frame, struct path path,
                                 struct rng *rng, struct render_counters *counters)
{
    struct path gather = {vec3(1, 1, 1), path.depth + 1, 1, 0, NO_LOBE};
    struct vec3 sum = vec3_zero();
    for (int j = 0; j < mode->sample_theta; j++)
        for (int k = 0; k < mode->sample_phi; k++) {
            struct vec3 wi;
            struct stratum_sample sample =
                gather_stratum(mode, s, frame, mode->sample_theta, mode->sample_phi, j, k,
                               gather, &wi, rng, counters);
            struct vec3 w = through != NULL ? brdf_eval(through, frame, s->wo, wi)
                                            : vec3(1.0, 1.0, 1.0);
            sum = vec3_add(sum, vec3_mul(w, sample.radiance));
        }
    return vec3_scale(sum, PI / (mode->sample_theta * mode->sample_phi));
}

/* The irradiance of multiple diffuse reflections at s: interpolated from the cache where
 * a record is usable (Ward 1988); else gathered, in the pre-pass into a new record, in the
 * final pass (a point no record covers) with the camera sample's share of a record's rays,
 * kept nowhere. */
static struct vec3 diffuse_interreflection(const struct jensen1994 *mode,
                                           const struct surface *s,
                                           const struct shading_frame *frame, struct path path,
                                           struct rng *rng, struct render_counters *counters)
{
    struct vec3 e;
    double a =
        mode->settings->cache_accuracy * (mode->filling_cache ? CACHE_FILL_STRICTNESS : 1.0);
    if (irradiance_cache_lookup(mode->cache, s->p, frame->n, a, &e))
        return e;
    if (!mode->filling_cache) {
        mode->stats->gather_fallbacks++;
        return sample_gather(mode, s, NULL, frame, path, rng, counters);
    }
    struct irradiance_record record = gather_record(mode, s, frame, path, rng, counters);
    irradiance_cache_add(mode->cache, &record);
    return record.e;
}

/* -- a surface, term by term -- */

/* Radiance leaving s towards s->wo on a path from the eye: L_e + L_r,s + L_r,d. */
static struct vec3 eye_radiance(const struct jensen1994 *mode, const struct surface *s,
                                struct path path, struct rng *rng,
                                struct render_counters *counters)
{
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct brdf_split split = brdf_split(s->material);
    struct vec3 l = surface_emission_found(mode, s, &path);
    if (split.has_diffuse) {
        l = vec3_add(l, direct_light(mode, s, &split.diffuse, &frame, rng, counters));
        l = vec3_add(l, caustic_light(mode, s, &split.diffuse, &frame));
        if (!split.lambertian) {
            /* Sec. 4.0.3: "surfaces with complex BRDF's are treated using plain recursive
             * Monte Carlo ray tracing". A diffuse-like part that is not Lambertian (a
             * broad lobe: Schlick's model with r >= 1/2) reflects int f_r,d L cos, which
             * depends on where the light comes from, so each camera sample gathers its
             * share through f_r,d itself, no cache. */
            l = vec3_add(l,
                         sample_gather(mode, s, &split.diffuse, &frame, path, rng, counters));
        } else {
            struct vec3 e = diffuse_interreflection(mode, s, &frame, path, rng, counters);
            l = vec3_add(l, diffuse_reflection(s, &split.diffuse, &frame, e));
        }
    }
    if (split.has_specular) {
        l = vec3_add(l, specular_light(mode, s, &split.specular, &frame, path, rng, counters));
        if (brdf_has_non_delta(&split.specular))
            l = vec3_add(l, lights_through_lobe(mode, s, &split.specular, &frame, rng,
                                                counters));
    }
    return l;
}

/* Radiance leaving s towards s->wo on a gather ray (Sec. 4.0.3): the diffuse-like part
 * reflects the irradiance of all photons, read from the photon map; the specular-like
 * part is followed on; emission only on a path from the eye (glossy_photons). */
static struct vec3 secondary_radiance(const struct jensen1994 *mode, const struct surface *s,
                                      struct path path, struct rng *rng,
                                      struct render_counters *counters)
{
    struct shading_frame frame = shading_frame_from_normal(s->ns, s->front, TRANSPORT_RADIANCE);
    struct brdf_split split = brdf_split(s->material);
    struct vec3 l = path.emission ? surface_emission_found(mode, s, &path) : vec3_zero();
    if (split.has_diffuse)
        l = vec3_add(l, stored_reflection(mode, s, &split.diffuse, &frame, &mode->all_photons,
                                          mode->precomputed));
    if (split.has_specular)
        l = vec3_add(l, specular_light(mode, s, &split.specular, &frame, path, rng, counters));
    return l;
}

static struct vec3 trace_from(const struct jensen1994 *mode, const struct surface *s,
                              struct path path, struct rng *rng,
                              struct render_counters *counters)
{
    return path.secondary ? secondary_radiance(mode, s, path, rng, counters)
                          : eye_radiance(mode, s, path, rng, counters);
}

static struct vec3 trace(const struct jensen1994 *mode, struct ray ray, struct path path,
                         struct rng *rng, struct render_counters *counters)
{
    struct surface s;
    double t;
    if (!ray_surface(mode->scene, ray, counters, &s, &t)) /* the sky, emission as any other */
        return path.emission ? emission_found(mode, mode->scene->sky, mode->scene->background,
                                              ray.origin, ray.dir, &path)
                             : vec3_zero();
    return trace_from(mode, &s, path, rng, counters);
}

static struct vec3 camera_ray_radiance(const void *mode, struct ray ray,
                                       const struct first_bounce *first, struct rng *rng,
                                       struct render_counters *counters)
{
    (void)first; /* its first bounce draws from the stream */
    struct path eye = {vec3(1, 1, 1), 0, 0, 1, NO_LOBE};
    return trace(mode, ray, eye, rng, counters);
}

/* ---- putting it together ---- */

/* The mode's state from the scene and the settings: estimates, strata, cache, scratch. */
static void set_up(struct jensen1994 *mode, const struct scene *scene,
                   const struct render_settings *rs, const struct jensen1994_settings *settings)
{
    struct aabb box = geometry_bounds(scene->geometry);
    mode->scene = scene;
    mode->settings = settings;
    mode->max_depth = rs->max_depth;
    mode->diagonal = scene_diagonal(scene);
    struct max_radii radii =
        max_radii_of(settings->max_radius, settings->caustic_radius_fraction, mode->diagonal);
    struct irradiance_settings all = {settings->gather, radii.all_r2, 0,
                                      settings->differential_run, settings->exclude_rim};
    mode->all_photons = all;
    mode->caustic_photons = all;
    mode->caustic_photons.max_r2 = radii.caustic_r2;
    mode->caustic_photons.kinds = PHOTON_CAUSTIC;
    /* Ward and Heckbert's strata, one ray each: a record's, and a camera sample's share */
    ward_strata(settings->gather_rays, &mode->strata_theta, &mode->strata_phi);
    ward_strata(settings->gather_rays / rs->spp, &mode->sample_theta, &mode->sample_phi);
    mode->light_strata = (int)floor(sqrt((double)settings->light_samples));
    mode->filling_cache = 0;
    mode->cache = irradiance_cache_create(isfinite(box.lo.x) ? box : (struct aabb){vec3_zero(),
                                                                               vec3_zero()},
                                       settings->cache_accuracy);
    mode->nn = nearest_create(settings->gather > PRECOMPUTED_CANDIDATES ? settings->gather
                                                                        : PRECOMPUTED_CANDIDATES);
    mode->strata = xmalloc((size_t)mode->strata_theta * (size_t)mode->strata_phi,
                           sizeof *mode->strata, "strata");
}

/* Christensen's records (--precomputed-irradiance N): every N-th photon of the map in its
 * tree's order, a sample spread over the whole map since each level of the heap spans
 * it, each holding the all-photons estimate a gather ray ending there would make. They
 * are made from the map alone, so a crop or a loaded map makes the same ones. */
static void precompute(struct jensen1994 *mode, const struct render_settings *rs)
{
    size_t step = (size_t)mode->settings->precomputed_irradiance;
    const struct kdtree *map = mode->stores.photons;
    if (step == 0 || map->n_photons == 0)
        return;
    clock_t start = clock();
    size_t n = (map->n_photons + step - 1) / step;
    struct photon *picked = xmalloc(n, sizeof *picked, "precomputed irradiance");
    for (size_t i = 0; i < n; i++)
        picked[i] = map->photons[1 + i * step];
    mode->records = balance_kdtree(picked, n);
    mode->stats->seconds_precompute = cpu_seconds(start);
    mode->precomputed = precompute_watched(map, mode->records, &mode->all_photons, NULL,
                                           rs->progress, &mode->stats->seconds_precompute);
    mode->stats->precomputed_records = n;
    mode->stats->bytes_precomputed =
        kdtree_bytes(mode->records) + precomputed_irradiance_bytes(mode->precomputed);
}

static void tear_down(struct jensen1994 *mode)
{
    precomputed_irradiance_free(mode->precomputed);
    kdtree_free(mode->records);
    xfree(mode->strata);
    nearest_free(mode->nn);
    irradiance_cache_free(mode->cache); /* mode->stores are the work's */
}

/* Pass 1 into work when it is empty (maps[0] the photon map, maps[1] the CP photons' tree,
 * maps[2] the glossy photons' (keeps_direction()), and the illumination maps when settings asks
 * for them), else the stores work holds (loaded from a file). mode->stores borrows them from
 * work. */
static int photon_stores(struct jensen1994 *mode, const struct scene *scene,
                         const struct render_settings *rs, struct global_work *work,
                         struct error *err)
{
    if (work->n_maps == 0) {
        if (jensen1994_trace(scene, rs->seed, rs->max_depth, mode->settings, &mode->stores,
                             mode->stats, rs->progress, err) < 0)
            return -1;
        global_work_add_maps(work, 3);
        work->maps[0] = mode->stores.photons;
        work->maps[1] = mode->stores.caustics;
        work->maps[2] = mode->stores.glossy;
        work->illumination = mode->stores.illumination;
        return 0;
    }
    if (work->n_maps != 3 || work->maps[0] == NULL || work->maps[1] == NULL ||
        work->maps[2] == NULL ||
        (work->illumination != NULL) != (mode->settings->illumination_maps != 0))
        return error_set(err, "", 0, "--load-photons: the file does not hold the three "
                                     "photon trees (and, with --irradiance-store "
                                     "illumination, the illumination maps) mode 1994 saves");
    mode->stores.photons = work->maps[0];
    mode->stores.caustics = work->maps[1];
    mode->stores.glossy = work->maps[2];
    mode->stores.illumination = work->illumination;
    if (work->illumination != NULL)
        count_illumination(work->illumination, mode->stats);
    mode->stats->photons_stored = work->maps[0]->n_photons + work->maps[2]->n_photons;
    mode->stats->photons_caustic = work->maps[1]->n_photons;
    mode->stats->photons_glossy = work->maps[2]->n_photons;
    mode->stats->bytes_photon_map = kdtree_bytes(work->maps[0]) + kdtree_bytes(work->maps[2]);
    mode->stats->bytes_caustic_photons = kdtree_bytes(work->maps[1]);
    return 0;
}

struct render_result render_jensen1994(const struct scene *scene,
                                       const struct render_settings *rs,
                                       const struct jensen1994_settings *settings,
                                       int want_variance, struct render_counters *counters,
                                       struct jensen1994_stats *stats, struct error *err)
{
    struct render_result result = {NULL, NULL, NULL, NULL, NULL, NULL, 0.0};
    memset(stats, 0, sizeof *stats);
    struct jensen1994 mode;
    memset(&mode, 0, sizeof mode);
    mode.stats = stats;
    mode.settings = settings;
    struct global_work own_work = {NULL, 0, NULL, 0, NULL}; /* without settings->work */
    struct global_work *work = settings->work != NULL ? settings->work : &own_work;
    int loaded = work->n_maps > 0;
    clock_t start = clock();
    if (photon_stores(&mode, scene, rs, work, err) < 0) {
        global_work_free(&own_work);
        return result;
    }
    stats->seconds_photons = cpu_seconds(start);
    set_up(&mode, scene, rs, settings);
    precompute(&mode, rs);
    stats->strata_theta = mode.strata_theta;
    stats->strata_phi = mode.strata_phi;
    start = clock();
    struct radiance_estimator estimator = {camera_ray_radiance, &mode, NULL};
    if (loaded) {
        global_work_fill_cache(work, mode.cache);
    } else {
        mode.filling_cache = 1;
        fill_cache_pass(scene, rs->seed, estimator, mode.cache, rs->progress, counters);
        mode.filling_cache = 0;
        global_work_keep_cache(work, mode.cache);
    }
    stats->seconds_cache = cpu_seconds(start);
    stats->cache_records = irradiance_cache_records(mode.cache);
    stats->bytes_cache = irradiance_cache_bytes(mode.cache);
    result = render_pixels(scene, rs, estimator, want_variance, NULL, counters);
    stats->seconds_final_pass = result.seconds;
    result.seconds += stats->seconds_photons + stats->seconds_cache;
    tear_down(&mode);
    global_work_free(&own_work);
    return result;
}
