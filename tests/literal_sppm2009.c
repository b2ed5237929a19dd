/*
 * tests/literal_sppm2009.c -- stochastic progressive photon mapping (Hachisuka and Jensen
 * 2009) as the paper writes it, and nothing else: the program to read before
 * src/modes/sppm2009.c. It calls the shared camera, ray casting, BRDFs and photon
 * tracer; it has none of the mode's departures (light samples, fitted radii, disc
 * coverage, the facing test, turned directions, glossy lobes followed), none of its
 * bookkeeping (error images, crops, time limits, progress, checkpoints) and no index of
 * hit points (each finds its photons itself). `photon --mode 2009 --paper` must agree with it
 * (tests/test_literal.c), so that the mode and the paper cannot drift apart. The photon
 * pass, Eq. 11 and the update, as 2008's, are in literal_photons.c.
 *
 * The algorithm, one pass after another:
 *   1. the distributed ray tracing pass: one new eye path a pixel, through the pixel's
 *      next camera sample, followed through mirrors and glass to the first surface with a
 *      non-specular part, where the pass's hit point lies, with its whole BRDF and the
 *      path's weight beta (2008, Sec. 3.1: "each ray path includes all specular bounces
 *      until the first non-specular surface seen");
 *   2. the photon tracing pass: M photons from the lights, stored where they hit;
 *   3. for each pixel, the photons within R of its hit point bring Phi = beta (sum of
 *      f_r(x, w, w_p) Phi_p) and M new photons, and the statistics the pixel's region S
 *      shares are updated as 2008's Eq. 7, 9 and 12:
 *          N' = N + alpha M,   R' = R sqrt((N + alpha M) / (N + M)),
 *          tau' = (tau + Phi) R'^2 / R^2;
 *   4. the image: L = tau / (pi R^2 N_e) (2008's Eq. 13, N_e the photons emitted so far)
 *      plus the emission the eye paths saw directly, averaged over the passes.
 *
 * Left open by the paper, and chosen as --paper chooses (sppm2009.c): R0 is one pixel's
 * footprint at the first hit point's distance; a surface with both a delta lobe and a
 * non-delta part stores its hit point or follows the delta lobe with even odds; eye paths
 * end by Russian roulette as pt's do.
 */
#include "literal_sppm2009.h"

#include "../src/base/alloc.h"
#include "../src/modes/render.h"
#include "../src/modes/surface.h"
#include "literal_photons.h"

/* What one pixel's region S keeps across passes (step 3), and its pass's hit point. */
struct region {
    double n, radius;      /* N and R (R = 0: no hit point yet, so no R0 either)        */
    struct vec3 tau;       /* the unnormalised flux                                     */
    struct vec3 emission;  /* the emission its eye paths saw, summed over the passes    */
    int has_point;         /* whether this pass's eye path found a hit point            */
    struct vec3 x, n_g, wo; /* the hit point: where, its surface's normal, towards the eye */
    struct shading_frame frame;
    const struct material *brdf;
    struct vec3 beta;      /* the eye path's weight                                     */
};

/* Step 1 for one pixel: its eye path of pass `pass`. */
static void trace_eye_path(const struct scene *scene, uint64_t seed, int x, int y, long pass,
                           struct region *s)
{
    struct rng rng;
    struct ray ray = camera_sample(scene, seed, x, y, (int)pass, &rng);
    struct vec3 beta = vec3(1.0, 1.0, 1.0);
    double distance = 0.0;
    s->has_point = 0;
    for (int depth = 0; depth < MAX_DEPTH_LIMIT; depth++) {
        struct surface at;
        double t;
        struct render_counters counters = {0};
        if (!ray_surface(scene, ray, &counters, &at, &t)) {
            s->emission = vec3_add(s->emission, vec3_mul(beta, scene->background));
            return;
        }
        distance += t;
        s->emission = vec3_add(s->emission, vec3_mul(beta, surface_emission(&at)));
        struct shading_frame frame = shading_frame_from_normal(at.ns, at.front,
                                                               TRANSPORT_RADIANCE);
        double p = !brdf_has_non_delta(at.material) ? 0.0 : brdf_has_delta(at.material) ? 0.5
                                                                                       : 1.0;
        if (p == 1.0 || (p > 0 && rng_uniform(&rng) < p)) { /* the hit point */
            s->has_point = 1;
            s->x = at.p;
            s->n_g = at.ng;
            s->wo = at.wo;
            s->frame = frame;
            s->brdf = at.material;
            s->beta = vec3_scale(beta, 1.0 / p);
            if (s->radius == 0) /* R0: one pixel's footprint there */
                s->radius = distance * camera_footprint(&scene->camera);
            return;
        }
        double u[3];
        rng_uniforms(&rng, u, 3);
        struct brdf_sample bs;
        if (!brdf_sample(at.material, &frame, at.wo, u, &bs) || !bs.delta)
            return; /* absorbed, or the non-delta part the hit point would have held */
        beta = vec3_scale(vec3_mul(beta, bs.weight), 1.0 / (1.0 - p));
        ray = surface_ray(&at, bs.wi, bs.transmitted);
        if (!survives_roulette(&beta, depth + 1, &rng))
            return;
    }
}

/* Step 3 for one region: the photons within R of its hit point bring beta times Eq. 11's
 * sum, and the statistics are updated. */
static void progressive_update(struct region *s, const struct literal_photons *pass,
                               size_t photons)
{
    if (!s->has_point)
        return;
    double m;
    struct vec3 found = literal_photons_within(pass, s->x, s->radius, s->brdf, &s->frame,
                                               s->wo, photons, &m);
    literal_update(&s->n, &s->radius, &s->tau, vec3_mul(s->beta, found), m);
}

struct image *literal_sppm2009(const struct scene *scene, uint64_t seed, long passes,
                               size_t photons_per_pass)
{
    int width = scene->width, height = scene->height;
    struct region *regions = xcalloc((size_t)width * (size_t)height, sizeof *regions,
                                     "literal regions");
    for (long pass = 0; pass < passes; pass++) {
        for (int y = 0; y < height; y++)
            for (int x = 0; x < width; x++)
                trace_eye_path(scene, seed, x, y, pass, &regions[(size_t)y * width + x]);
        struct literal_photons photons = literal_photon_pass(scene, seed, pass,
                                                             photons_per_pass);
        for (size_t i = 0; i < (size_t)width * (size_t)height; i++)
            progressive_update(&regions[i], &photons, photons_per_pass);
        literal_photons_free(&photons);
    }
    struct image *image = image_create(width, height);
    double emitted = (double)passes * (double)photons_per_pass; /* N_e */
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            const struct region *s = &regions[(size_t)y * width + x];
            struct vec3 l = vec3_scale(s->emission, 1.0 / (double)passes);
            if (s->radius > 0)
                l = vec3_add(l, vec3_scale(s->tau, 1.0 / (PI * s->radius * s->radius *
                                                          emitted)));
            image_set(image, x, y, l);
        }
    xfree(regions);
    return image;
}
