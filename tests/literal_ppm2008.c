/*
 * tests/literal_ppm2008.c -- progressive photon mapping (Hachisuka, Ogaki and Jensen 2008)
 * as the paper writes it, and nothing else: the program to read before
 * src/modes/ppm2008.c. It calls the shared camera, ray casting, BRDFs and photon tracer;
 * it has none of the mode's departures (light samples, new eye rays each pass, merged hit
 * points, fitted radii, caustic estimates apart, the facing test, turned directions),
 * none of its bookkeeping and no index of hit points (each finds its photons itself).
 * `photon --mode 2008 --paper` must agree with it (tests/test_literal.c). The photon pass,
 * Eq. 11 and the update, which 2009's literal program shares, are in literal_photons.c.
 *
 * The algorithm (Sec. 3.1 and 4):
 *   1. the ray tracing pass, once: --spp eye rays a pixel "using standard ray tracing",
 *      each followed through mirrors and glass (every lobe, as Whitted's tracer), storing
 *      a hit point wherever it meets a surface with a non-specular part: its place, the
 *      ray's direction, the whole BRDF, the pixel and its weight (the path's throughput
 *      over the pixel's rays), with R = R0, N = 0, tau = 0;
 *   2. each photon tracing pass: M photons from the lights, stored where they hit;
 *   3. each hit point takes the photons within R: tau_M = sum of f_r(x, w, w_p) Phi_p
 *      (Eq. 11), M of them, and then (Eq. 7, 9, 12)
 *          N' = N + alpha M,   R' = R sqrt((N + alpha M) / (N + M)),
 *          tau' = (tau + tau_M) R'^2 / R^2;
 *   4. the image: each pixel sums its hit points' weight times tau / (pi R^2 N_e) (Eq. 13,
 *      N_e the photons emitted so far), plus the emission its eye rays saw directly.
 *
 * Left open by the paper, and chosen as --paper chooses (ppm2008.c): R0 is one pixel's
 * footprint at the hit point's distance; a surface with a delta lobe beside a non-delta
 * part (Schlick's r < 1/2) follows its one sampled direction when it is the delta lobe's;
 * eye paths end by Russian roulette after 8 bounces.
 */
#include "literal_ppm2008.h"

#include <string.h>

#include "../src/base/alloc.h"
#include "../src/modes/render.h"
#include "../src/modes/surface.h"
#include "literal_photons.h"

#define ROULETTE_BOUNCES 8  /* mirror and glass bounces before Russian roulette         */

/* A hit point of step 1 with its statistics. */
struct hit_point {
    struct vec3 x, wo; /* where, towards the eye                                     */
    struct shading_frame frame;
    const struct material *brdf;
    size_t pixel;
    struct vec3 weight; /* the path's throughput over the pixel's eye rays            */
    double n, radius;
    struct vec3 tau;
};

/* What step 1 makes: the hit points and each pixel's emission seen. */
struct ray_tracing_pass {
    const struct scene *scene;
    struct hit_point *points;
    size_t n, capacity;
    struct vec3 *emission;
    int spp;
};

static void store_hit_point(struct ray_tracing_pass *pass, const struct surface *s,
                            const struct shading_frame *frame, size_t pixel, struct vec3 beta,
                            double distance)
{
    if (pass->n == pass->capacity) {
        pass->capacity = pass->capacity > 0 ? 2 * pass->capacity : 1024;
        pass->points = xrealloc(pass->points, pass->capacity, sizeof *pass->points,
                                "literal hit points");
    }
    struct hit_point *hp = &pass->points[pass->n++];
    memset(hp, 0, sizeof *hp);
    hp->x = s->p;
    hp->wo = s->wo;
    hp->frame = *frame;
    hp->brdf = s->material;
    hp->pixel = pixel;
    hp->weight = vec3_scale(beta, 1.0 / pass->spp);
    hp->radius = distance * camera_footprint(&pass->scene->camera); /* R0 */
}

/* Step 1 for one eye ray (or the part of it a lobe took) of window pixel `pixel`. */
static void trace_eye_ray(struct ray_tracing_pass *pass, struct ray ray, size_t pixel,
                          struct vec3 beta, double distance, int bounces, struct rng *rng)
{
    struct surface s;
    double t;
    struct render_counters counters = {0};
    if (!ray_surface(pass->scene, ray, &counters, &s, &t)) {
        pass->emission[pixel] = vec3_add(pass->emission[pixel],
                                         vec3_mul(beta, pass->scene->background));
        return;
    }
    distance += t;
    pass->emission[pixel] = vec3_add(pass->emission[pixel],
                                     vec3_mul(beta, surface_emission(&s)));
    struct shading_frame frame = shading_frame_from_normal(s.ns, s.front, TRANSPORT_RADIANCE);
    if (brdf_has_non_delta(s.material))
        store_hit_point(pass, &s, &frame, pixel, beta, distance);
    if (bounces >= MAX_DEPTH_LIMIT)
        return;
    struct brdf_sample lobes[2];
    int n = 0;
    if (brdf_is_delta(s.material)) {
        n = brdf_delta_lobes(s.material, &frame, s.wo, lobes);
    } else if (brdf_has_delta(s.material)) {
        double u[3];
        rng_uniforms(rng, u, 3);
        n = brdf_sample(s.material, &frame, s.wo, u, &lobes[0]) && lobes[0].delta;
    }
    for (int k = 0; k < n; k++) {
        struct vec3 b = vec3_mul(beta, lobes[k].weight);
        if (bounces + 1 >= ROULETTE_BOUNCES && !survives_roulette(&b, bounces + 1, rng))
            continue;
        trace_eye_ray(pass, surface_ray(&s, lobes[k].wi, lobes[k].transmitted), pixel, b,
                      distance, bounces + 1, rng);
    }
}

/* Step 3 for one hit point: Eq. 11's sum over the photons within R, and the update. */
static void progressive_update(struct hit_point *hp, const struct literal_photons *pass,
                               size_t photons)
{
    double m;
    struct vec3 tau_m = literal_photons_within(pass, hp->x, hp->radius, hp->brdf,
                                               &hp->frame, hp->wo, photons, &m);
    literal_update(&hp->n, &hp->radius, &hp->tau, tau_m, m);
}

struct image *literal_ppm2008(const struct scene *scene, uint64_t seed, int spp, long passes,
                              size_t photons_per_pass)
{
    int width = scene->width, height = scene->height;
    struct ray_tracing_pass pass = {scene, NULL, 0, 0, NULL, spp};
    pass.emission = xcalloc((size_t)width * (size_t)height, sizeof *pass.emission,
                            "literal emission");
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            for (int s = 0; s < spp; s++) {
                struct rng rng;
                struct ray ray = camera_sample(scene, seed, x, y, s, &rng);
                trace_eye_ray(&pass, ray, (size_t)y * width + x, vec3(1.0, 1.0, 1.0), 0.0, 0,
                              &rng);
            }
    for (long p = 0; p < passes; p++) {
        struct literal_photons photons = literal_photon_pass(scene, seed, p, photons_per_pass);
        for (size_t i = 0; i < pass.n; i++)
            progressive_update(&pass.points[i], &photons, photons_per_pass);
        literal_photons_free(&photons);
    }
    struct image *image = image_create(width, height);
    for (size_t i = 0; i < (size_t)width * (size_t)height; i++)
        image->pixels[i] = vec3_scale(pass.emission[i], 1.0 / spp);
    double emitted = (double)passes * (double)photons_per_pass; /* N_e */
    for (size_t i = 0; i < pass.n; i++) {
        const struct hit_point *hp = &pass.points[i];
        if (hp->radius > 0)
            image->pixels[hp->pixel] = vec3_add(
                image->pixels[hp->pixel],
                vec3_mul(hp->weight, vec3_scale(hp->tau, 1.0 / (PI * hp->radius * hp->radius *
                                                                emitted))));
    }
    xfree(pass.points);
    xfree(pass.emission);
    return image;
}
