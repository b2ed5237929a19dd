/*
 * modes/sppm2009.c -- `--mode 2009`: stochastic progressive photon mapping (Hachisuka and
 * Jensen 2009), read top to bottom as the paper's algorithm.
 *
 * Progressive photon mapping (ppm2008.c) estimates the radiance at fixed points, the hit
 * points of eye rays traced once; a pixel, the mean over its square, then keeps the
 * aliasing of those few rays however long the render runs, and so does anything else
 * that needs many eye paths a pixel (glossy reflections seen by the eye, a light's
 * outline). The 2009 paper estimates the mean radiance over a region S instead -- here
 * the part of the scene a pixel sees -- with statistics that S's points share:
 *
 *   shared statistics: per pixel, the photon count N, the radius R and the unnormalised
 *       flux tau, kept across passes (struct progressive_estimate); nothing else stays;
 *   each pass, the distributed ray tracing pass: one new eye path per pixel (its next
 *       point of the pixel's camera sequence), followed through mirrors and glass by
 *       sampling them (Russian roulette on long chains) to the first non-specular
 *       surface: that pass's hit point of S, with its BRDF and path weight beta;
 *   then a photon tracing pass with the shared tracer: every photon within R of a hit
 *       point adds f_r Phi' to it, as in 2008 (hit_point_add_photon());
 *   then, per pixel, the progressive update with the pass's Phi = beta (sum f_r Phi'):
 *       N <- N + alpha M,  R <- R sqrt((N + alpha M) / (N + M)),  tau <- (tau + Phi) R'^2 / R^2,
 *       which is 2008's Eq. 7, 9 and 12 applied to S's shared values (ppm_update_estimate());
 *   the image: L = tau / (pi R^2 N_emitted) (2008's Eq. 13) plus the emission the eye paths
 *       saw directly, averaged over the passes.
 *
 * The photon search finds the pass's hit points (at most one a pixel) in 2008's kd-tree
 * of hit points (photon/hit_points.h), built anew each pass: one index for both modes. A
 * hash grid gives the same image to the bit and is a little faster here, but much slower
 * for 2008, whose discs differ in size far more (src/modes/measured.md). The memory is
 * O(pixels) and does not grow with the passes.
 *
 * The initial radius: R0 of a pixel is ppm_initial_radius() at the first hit point it
 * gets: --footprints widths of a pixel at that distance, fitted to the surface
 * (ppm_radius.c), so it scales with the scene; pbrt's default of one world unit is
 * wrong in millimetres and in kilometres. --radius sets it in scene units.
 *
 * The disc coverage (--disc-coverage): by a corner or an open edge part of a hit point's
 * disc lies off its surface, where no photon lands though pi R^2 counts it, and the pixel
 * is dark by that part. 2008 shortens each hit point's R0 until its disc lies on the
 * surface; here a pixel's radius is shared by hit points anywhere in its square, and one
 * short enough for all of them is noise for all of them (the figures:
 * src/modes/README.md). Instead each pass probes one point of its hit point's
 * disc (disc_probe_beside(), which also counts no point behind a wall; the pass-th point
 * of the pixel's own shuffled (0,2)-sequence), and
 * the image divides the pixel's photon estimate by the share of its probes that found the
 * surface: tau / (pi R^2) is the sum over the passes of Phi_i / (pi R_i^2) (Eq. 12 keeps
 * it), each of which is on average the photon density times its disc's covered share c_i,
 * so the sum is short by the mean of the c_i, which the probes estimate without bias. A
 * photon counts on a disc as the probes see the disc (disc_holds_photon()). R0 is then
 * fitted only to walls the surface goes on past, whose far side's photons the coverage
 * would count as the disc's own (ppm_radius.c). A pixel's radius is fitted at its first
 * hit point, and that fit knows only its surface: a pixel that also sees another (the
 * ceiling beside a lamp's shroud, first met on the shroud's side) fits again at each hit
 * point off the first one's plane, and a shorter fit shrinks the shared disc
 * (shrink_estimate()).
 *
 * Departures, as in 2008, each with its switch, off under --paper:
 *   the direct light (--no-direct-light-samples is the paper's way) by one
 *       shadow-tested light sample at each pass's hit point (ppm_direct.c), photons
 *       counted only after their first bounce (caustics still count): the paper
 *       estimates it from photons too;
 *   the fitted initial radius (--fit-radius) and R0 in footprints: the paper leaves R0
 *       to the user;
 *   the disc coverage (--disc-coverage), above;
 *   turned photon directions (--turn-photon-directions), as 2008's;
 *   glossy lobes followed (--follow-glossy-lobes): the eye path samples a glossy lobe
 *       as it does a mirror, and the hit point takes the diffuse part alone
 *       (split_choice()); the paper's hit point takes the whole BRDF (paper_choice()).
 *
 * The error image (--error, --target-error; sppm_error.h): each pass also hands every
 * pixel's pass value y_i and the value y'_i over the inner disc of radius R_i / sqrt(2)
 * (add_pass_values(), before the update) to the pixel's batches; the window kept grows
 * by SPPM_ERROR_MARGIN pixels each side (inside the image), which the bound of a pixel
 * near the edge reads, so that a crop's error image is its window of the whole's; the
 * image is the written window's alone (kept_pixel(), sppm_error.h's kept_window).
 *
 * Determinism: eye path p of pixel (x, y) is camera sample p (render.h: its stream is
 * keyed by the pixel and p), its light samples are keyed by the pixel and the pass
 * (ppm_direct.h), its disc probes by the pixel and the pass, photon i of pass p by
 * (seed, photon, p, i); a pixel's statistics take only its own hit point's photons, so
 * the image does not depend on the window.
 */
#include "sppm2009.h"

#include <stdio.h>
#include <string.h>
#include <time.h>

#include "../base/alloc.h"
#include "../base/sequence02.h"
#include "../image/error_image.h"
#include "../photon/disc_coverage.h"
#include "../photon/hit_points.h"
#include "../photon/trace.h"
#include "pixel_error.h"
#include "ppm_direct.h"
#include "ppm_radius.h"
#include "sppm_error.h"
#include "surface.h"

/* The probes of one pixel's discs, one a pass, and how many found the surface. */
struct disc_share {
    uint32_t probes;
    uint32_t covered;
};

/* The plane of the hit point a pixel's radius was fitted at: its point and unit normal. */
struct fitted_plane {
    struct vec3 x;
    struct vec3 n;
};

struct sppm {
    const struct scene *scene;          /* borrowed                                        */
    const struct render_settings *rs;   /* &kept.grown                                     */
    struct kept_window kept;            /* the caller's window, grown by SPPM_ERROR_MARGIN
                                           with an error image (inside the image): the
                                           pixels kept                                     */
    const struct sppm_settings *ps;     /* borrowed                                        */
    struct render_counters *counters;   /* borrowed                                        */
    struct ppm_stats *stats;            /* borrowed: gets the eye paths' seconds, mean R0   */
    size_t n_pixels;                    /* of the window kept                              */
    struct progressive_estimate *shared; /* owned: per window pixel, S's N, R and tau; R is
                                            0 until the pixel's first hit point            */
    struct vec3 *emission_seen;         /* owned: per window pixel, the sum over passes of
                                           the emission and background its paths saw      */
    struct hit_point *points;           /* owned: this pass's hit points, n_points of them,
                                           room for one a pixel                            */
    size_t n_points;
    struct hit_point_tree tree;         /* over points, built anew each pass, which moves
                                           them into its order                             */
    const struct photon_event *photon;  /* the photon being added                          */
    double photons_per_pass;            /* turns the tracer's Phi / N back into the
                                           paper's unnormalised Phi'                       */
    long passes_done;
    struct ppm_direct direct;           /* the direct term, unless the photons bring it    */
    struct brdf_split *parts;           /* owned: each scene material's diffuse and
                                           specular parts (brdf_split())                   */
    struct disc_share *coverage;        /* owned, with ps->disc_coverage: per window pixel,
                                           its probes of its hit points' discs            */
    struct fitted_plane *fitted;        /* owned, with ps->disc_coverage: per window pixel,
                                           the plane its radius was fitted on             */
    int want_error;                     /* rs->error_confidence > 0                        */
    struct sppm_error error;            /* with want_error, and with it: ...               */
    struct vec3 *pass_photons;          /* owned: 2 per window pixel, this pass's P_i and
                                           P'_i (add_pass_values())                        */
    struct vec3 *inner_tau;             /* owned: per window pixel, this pass's f_r Phi' of
                                           the photons within R / sqrt(2) of its hit point */
    uint32_t *inner_probes;             /* owned: 2 per window pixel, the disc probes that
                                           fell in the inner disc and those of them that
                                           found the surface                               */
};


/* ---- the distributed ray tracing pass ----------------------------------------------- */

/* Shrinks the disc of e to radius r < e->radius, keeping its photon density and its
 * estimate: tau / (pi R^2) and N / (pi R^2) stay, as Eq. 12 keeps them when R shrinks. */
static void shrink_estimate(struct progressive_estimate *e, double r)
{
    double ratio2 = (r / e->radius) * (r / e->radius);
    e->tau = vec3_scale(e->tau, ratio2);
    e->n_photons *= ratio2;
    e->radius = r;
}

/* With the disc coverage, the fit of window pixel `pixel`'s shared radius to the walls
 * that its hit point at s sees: the first hit point's fit is the radius itself and its
 * plane is kept; a hit point off that plane (turned 60 degrees or more from it, or
 * farther from it than the radius) is fitted again, and a shorter fit shrinks the disc. */
static void fit_to_surface(struct sppm *sppm, size_t pixel, const struct surface *s,
                           double distance)
{
    struct fitted_plane *plane = &sppm->fitted[pixel];
    struct progressive_estimate *shared = &sppm->shared[pixel];
    if (vec3_length2(plane->n) == 0) { /* the first hit point: its fit is the radius */
        plane->x = s->p;
        plane->n = s->ng;
        return;
    }
    if (vec3_dot(plane->n, s->ng) >= DISC_SAME_SURFACE_COS &&
        fabs(vec3_dot(vec3_sub(s->p, plane->x), plane->n)) <= shared->radius)
        return;
    double r = ppm_initial_radius(sppm->scene, &sppm->ps->progressive,
                                   sppm->ps->disc_coverage, sppm->counters, s, distance);
    if (r < shared->radius)
        shrink_estimate(shared, r);
}

/* The pass's hit point of window pixel `pixel` at s, reached with throughput beta after
 * `distance` along its eye path; its disc is the pixel's shared radius, R0 at its first. */
static void store_hit_point(struct sppm *sppm, size_t pixel, const struct surface *s,
                            const struct shading_frame *frame, struct vec3 beta,
                            double distance)
{
    struct progressive_estimate *shared = &sppm->shared[pixel];
    const struct progressive_settings *common = &sppm->ps->progressive;
    if (shared->radius == 0)
        shared->radius = ppm_initial_radius(sppm->scene, common, sppm->ps->disc_coverage,
                                            sppm->counters, s, distance);
    if (sppm->ps->disc_coverage && common->fit_radius && common->radius <= 0)
        fit_to_surface(sppm, pixel, s, distance); /* else no fit could shorten R */
    if (sppm->want_error)
        sppm->inner_tau[pixel] = vec3_zero();
    struct hit_point *hp = &sppm->points[sppm->n_points++];
    hp->x = s->p;
    hp->n = s->ng;
    hp->wo = s->wo;
    hp->frame = *frame;
    hp->material = s->material;
    hp->pixel = pixel;
    hp->weight = beta;
    hp->global.radius = shared->radius;
    hp->global.n_photons = 0;
    hp->global.tau = vec3_zero();
    hp->global.m_photons = 0;
    hp->caustic = hp->global;
    hp->caustic.radius = 0; /* one estimate: the paper's */
    hp->members = NULL; /* a hit point an eye path */
    hp->n_members = 0;
    hp->spread = 0.0;
}

/* The pass's probe of the disc of window pixel `pixel`'s hit point at s (see the top). */
static void probe_disc(struct sppm *sppm, size_t pixel, long pass, const struct surface *s)
{
    struct rng order = rng_stream(sppm->rs->seed, STREAM_DISC,
                                  image_pixel(sppm->rs, sppm->scene->width, pixel), 0);
    uint64_t shift = rng_next(&order);
    double u, v;
    sequence02_point(sequence02_shuffled((uint32_t)pass, (uint32_t)rng_next(&order)),
                     (uint32_t)shift, (uint32_t)(shift >> 32), &u, &v);
    struct disc_share *share = &sppm->coverage[pixel];
    int covered = disc_probe_beside(sppm->scene, s->p, s->ng, sppm->shared[pixel].radius,
                                    u, 2 * PI * v);
    share->probes++;
    share->covered += (uint32_t)covered;
    if (sppm->want_error && u < 0.5) { /* within R / sqrt(2): the inner disc's probe too */
        sppm->inner_probes[2 * pixel]++;
        sppm->inner_probes[2 * pixel + 1] += (uint32_t)covered;
    }
}

/* The probability that an eye path at a surface with these parts ends there, in a hit
 * point for the diffuse part, rather than going on along the specular part (a glossy
 * lobe, a mirror, glass): 1 without a specular part, 0 without a diffuse one, else the
 * diffuse part's share of the two albedos seen from wo. */
static double hit_point_probability(const struct brdf_split *part,
                                    const struct shading_frame *frame, struct vec3 wo)
{
    if (!part->has_specular)
        return 1.0;
    if (!part->has_diffuse)
        return 0.0;
    double d = vec3_luminance(brdf_albedo(&part->diffuse, frame, wo));
    double g = vec3_luminance(brdf_albedo(&part->specular, frame, wo));
    return d + g > 0 ? d / (d + g) : 0.5;
}

/* With light-sampled direct light (a departure, the top of the file): a glossy lobe, the
 * k-th surface of the eye path of window pixel `pixel` at s, which the path follows with
 * throughput beta, samples the point lights through itself: its sampled directions find
 * every other light, never a point light's highlight (without it the sphere flake's Phong
 * spheres are dark: src/modes/README.md). */
static void point_lights_through_lobe(struct sppm *sppm, size_t pixel, long pass, uint64_t k,
                                      const struct surface *s, const struct material *lobe,
                                      const struct shading_frame *frame, struct vec3 beta)
{
    if (!sppm->ps->progressive.direct_light_samples || !brdf_has_non_delta(lobe))
        return;
    struct surface glossy = *s;
    glossy.material = lobe;
    ppm_direct_point_lights(&sppm->direct, pixel, k, pass, &glossy, frame, beta,
                            sppm->counters);
}

/* How an eye path goes on at a surface: with probability p it ends there in a hit point
 * that takes the material `stored` (NULL: black, the path ends with nothing); otherwise it
 * samples `followed` and goes on, a non-delta sample of it ending the path when
 * delta_only (the hit point holds that light). */
struct path_choice {
    double p;
    const struct material *stored, *followed;
    int delta_only;
};

/* The paper's (--no-follow-glossy-lobes): "each ray path includes all specular bounces
 * until the first non-specular surface seen" (2008, Sec. 3.1, which 2009's pass
 * repeats), and the hit point there takes the whole BRDF. A surface with both a delta
 * lobe and a non-delta part (Schlick's r < 1/2) is not specified by the paper, whose
 * path keeps one hit point: it stores one or follows a delta lobe with even odds. */
static struct path_choice paper_choice(const struct material *m)
{
    struct path_choice c = {0.0, m, m, 1};
    if (brdf_has_non_delta(m))
        c.p = brdf_has_delta(m) ? 0.5 : 1.0;
    return c;
}

/* The departure (--follow-glossy-lobes): the path ends at a surface's diffuse part (the
 * split of brdf.h: Lambertian terms, broad lobes), whose hit point takes that part's
 * BRDF; a specular part -- a mirror, glass, a glossy lobe -- is sampled and followed, as
 * a path tracer would: a photon estimate behind a narrow lobe is mostly noise
 * (tests/test_sppm.c's glossy floor). A surface with both chooses one by
 * hit_point_probability(). */
static struct path_choice split_choice(const struct brdf_split *part, const struct material *m,
                                       const struct shading_frame *frame, struct vec3 wo)
{
    struct path_choice c;
    c.p = hit_point_probability(part, frame, wo);
    c.stored = !part->has_diffuse ? NULL : part->has_specular ? &part->diffuse : m;
    c.followed = part->has_diffuse ? &part->specular : m;
    c.delta_only = 0;
    return c;
}

/* Eye path `pass` of window pixel `pixel` along ray: what emitters and the background
 * show along it goes to the pixel's seen sum; it ends in the pass's hit point at the
 * surface path_choice names, the weight divided by the probability of each choice made,
 * so each part counts once, unbiased. */
static void trace_eye_path(struct sppm *sppm, size_t pixel, long pass, struct ray ray,
                           struct rng *rng)
{
    struct vec3 beta = vec3(1.0, 1.0, 1.0);
    double distance = 0.0;
    for (int depth = 0;; depth++) {
        struct surface s;
        double t;
        if (!ray_surface(sppm->scene, ray, sppm->counters, &s, &t)) {
            sppm->emission_seen[pixel] = vec3_add(sppm->emission_seen[pixel],
                                                  vec3_mul(beta, sppm->scene->background));
            return;
        }
        distance += t;
        sppm->emission_seen[pixel] = vec3_add(sppm->emission_seen[pixel],
                                              vec3_mul(beta, surface_emission(&s)));
        if (depth >= sppm->rs->max_depth)
            return;
        struct shading_frame frame = shading_frame_from_normal(s.ns, s.front,
                                                               TRANSPORT_RADIANCE);
        struct path_choice c =
            sppm->ps->follow_glossy_lobes
                ? split_choice(&sppm->parts[s.material - sppm->scene->materials], s.material,
                               &frame, s.wo)
                : paper_choice(s.material);
        if (c.p < 1 && (c.p == 0 || rng_uniform(rng) >= c.p)) {
            double u[3];
            rng_uniforms(rng, u, 3);
            struct brdf_sample bs;
            if (!c.delta_only)
                point_lights_through_lobe(sppm, pixel, pass, (uint64_t)depth + 1, &s,
                                          c.followed, &frame, vec3_scale(beta, 1.0 / (1.0 - c.p)));
            if (!brdf_sample(c.followed, &frame, s.wo, u, &bs) || (c.delta_only && !bs.delta))
                return;
            beta = vec3_scale(vec3_mul(beta, bs.weight), 1.0 / (1.0 - c.p));
            ray = surface_ray(&s, bs.wi, bs.transmitted);
            if (!survives_roulette(&beta, depth + 1, rng))
                return;
            continue;
        }
        if (c.stored == NULL)
            return; /* black: reflects nothing */
        s.material = c.stored;
        beta = vec3_scale(beta, 1.0 / c.p);
        store_hit_point(sppm, pixel, &s, &frame, beta, distance);
        if (sppm->ps->disc_coverage)
            probe_disc(sppm, pixel, pass, &s);
        if (sppm->ps->progressive.direct_light_samples)
            ppm_direct_sample(&sppm->direct, pixel, 0, pass, &s, &frame, beta, sppm->counters);
        return;
    }
}

/* The mean R over the written pixels that have one: the progress line's and --stats's. */
static double mean_radius(const void *context)
{
    const struct sppm *sppm = context;
    double sum = 0.0;
    size_t n = 0;
    for (size_t k = 0; k < (size_t)sppm->kept.out_width * (size_t)sppm->kept.out_height; k++) {
        double r = sppm->shared[kept_pixel(&sppm->kept, k)].radius;
        if (r > 0) {
            sum += r;
            n++;
        }
    }
    return n > 0 ? sum / (double)n : 0.0;
}

/* What pixel i's eye paths saw and its direct term, summed over the passes so far. */
static struct vec3 seen_so_far(const struct sppm *sppm, size_t i)
{
    struct vec3 seen = sppm->emission_seen[i];
    return sppm->ps->progressive.direct_light_samples ? vec3_add(seen, sppm->direct.sum[i])
                                                      : seen;
}

/* Pass `pass`: one eye path through every pixel of the window, then the hit points' tree;
 * its CPU seconds go to the stats, and after the first pass the mean R0. */
static void distributed_ray_tracing_pass(void *context, long pass)
{
    struct sppm *sppm = context;
    const struct render_settings *rs = sppm->rs;
    clock_t start = clock();
    sppm->n_points = 0;
    for (size_t i = 0; sppm->want_error && i < sppm->n_pixels; i++)
        sppm->error.before[i] = seen_so_far(sppm, i);
    for (int y = rs->y0; y < rs->y1; y++)
        for (int x = rs->x0; x < rs->x1; x++) {
            size_t pixel = (size_t)(y - rs->y0) * (size_t)sppm->kept.width +
                           (size_t)(x - rs->x0);
            struct rng rng;
            struct ray ray = camera_sample(sppm->scene, rs->seed, x, y, (int)pass, &rng);
            trace_eye_path(sppm, pixel, pass, ray, &rng);
        }
    hit_point_tree_free(&sppm->tree);
    hit_point_tree_build(&sppm->tree, sppm->points, sppm->n_points);
    sppm->stats->seconds_ray_pass += cpu_seconds(start);
    if (pass == 0)
        sppm->stats->initial_mean_radius = mean_radius(sppm);
}

/* ---- the photon tracing pass ----------------------------------------------------------- */

static void add_flux(void *context, size_t i)
{
    struct sppm *sppm = context;
    const struct hit_point *hp = &sppm->points[i];
    if (sppm->ps->disc_coverage && !disc_holds_photon(hp->x, hp->n, hp->global.radius,
                                                      sppm->photon->position,
                                                      sppm->photon->normal))
        return;
    /* No facing test (2008's): with the disc coverage, disc_holds_photon() keeps only
     * photons on a surface facing the hit point's; without it every photon within R
     * counts, the paper's way. */
    hit_point_add_photon(&sppm->points[i], sppm->photon, sppm->photons_per_pass, 0,
                         sppm->ps->progressive.turn_photon_directions, 0,
                         sppm->want_error ? &sppm->inner_tau[hp->pixel] : NULL);
}

/* Each photon a photon tracing pass stores (2008's pass) goes to the hit points around
 * it. */
static void add_photon(void *context, const struct photon_event *photon)
{
    struct sppm *sppm = context;
    sppm->photon = photon;
    hit_point_tree_visit(&sppm->tree, photon->position, add_flux, sppm);
}

/* ---- the progressive update of the shared statistics ---------------------------------- */

/* The mean covered share of pixel i's discs, by its probes (1 without them), never below
 * DISC_COVERAGE_FLOOR, which bounds how far a few unlucky probes can brighten it. */
static double covered_share(const struct sppm *sppm, size_t i)
{
    if (!sppm->ps->disc_coverage || sppm->coverage[i].probes == 0)
        return 1.0;
    const struct disc_share *share = &sppm->coverage[i];
    return fmax(DISC_COVERAGE_FLOOR, (double)share->covered / share->probes);
}

/* As covered_share(), the inner disc's (radius R / sqrt(2)), by the probes that fell in
 * it; the whole disc's while none has. */
static double inner_share(const struct sppm *sppm, size_t i)
{
    const uint32_t *probes = &sppm->inner_probes[2 * i];
    if (!sppm->ps->disc_coverage || probes[0] == 0)
        return covered_share(sppm, i);
    return fmax(DISC_COVERAGE_FLOOR, (double)probes[1] / probes[0]);
}

/* With an error image, before the update: each pixel's pass values (sppm_error.h), e_i
 * what its eye path saw and its direct light, P_i = beta Phi_i / (pi R_i^2 M) its photon
 * estimate (the pass's share of Eq. 13: tau / (pi R^2) is the sum over the passes of
 * Phi_i / (pi R_i^2), Eq. 12 keeping it, the top of the file) and P'_i the same over the
 * inner disc of radius R_i / sqrt(2); the covered shares divide them later
 * (state_shares()). */
static void add_pass_values(struct sppm *sppm, long pass)
{
    struct sppm_error *e = &sppm->error;
    struct vec3 *photons = sppm->pass_photons; /* zero for a pixel without a hit point */
    memset(photons, 0, 2 * sppm->n_pixels * sizeof *photons);
    for (size_t k = 0; k < sppm->n_points; k++) { /* in the order they lie in memory */
        const struct hit_point *hp = &sppm->points[k];
        sppm_error_photons(hp->weight, hp->global.radius, hp->global.tau,
                           sppm->inner_tau[hp->pixel], sppm->photons_per_pass,
                           &photons[2 * hp->pixel], &photons[2 * hp->pixel + 1]);
    }
    for (size_t i = 0; i < sppm->n_pixels; i++) {
        struct vec3 seen = vec3_sub(seen_so_far(sppm, i), e->before[i]);
        sppm_error_add_pass(e, i, seen, photons[2 * i], photons[2 * i + 1]);
    }
    sppm_error_pass_done(e, pass);
}

/* Before the error image is made: each pixel's covered shares as the image has them,
 * c of its discs and c' of their inner discs (sppm_error_add_pass()). */
static void state_shares(struct sppm *sppm)
{
    for (size_t i = 0; i < sppm->n_pixels; i++) {
        sppm->error.shares[2 * i] = covered_share(sppm, i);
        sppm->error.shares[2 * i + 1] = inner_share(sppm, i);
    }
}

/* Each hit point's Phi = beta (sum of f_r Phi') goes to its pixel's tau, and its M to the
 * update (ppm_update_estimate(): N, R, tau); a pixel without a hit point this pass found
 * no photon (M = 0) and keeps its values. */
static void progressive_update(void *context, long pass)
{
    struct sppm *sppm = context;
    if (sppm->want_error)
        add_pass_values(sppm, pass);
    for (size_t i = 0; i < sppm->n_points; i++) {
        const struct hit_point *hp = &sppm->points[i];
        struct progressive_estimate *shared = &sppm->shared[hp->pixel];
        shared->tau = vec3_add(shared->tau, vec3_mul(hp->weight, hp->global.tau));
        shared->m_photons = hp->global.m_photons;
        ppm_update_estimate(shared, sppm->ps->progressive.alpha);
    }
    if (sppm->ps->progressive.direct_light_samples)
        ppm_direct_end_pass(&sppm->direct);
    sppm->passes_done++;
}

/* ---- the image ---------------------------------------------------------------------- */

/* The image so far: per pixel, the photons' tau / (pi R^2 N_emitted), over the covered
 * share of its discs, plus the mean of what the eye paths saw directly and, unless
 * photons bring it, of their direct light. */
static void evaluate_image(const void *context, double n_emitted, struct image *image)
{
    const struct sppm *sppm = context;
    double passes = sppm->passes_done > 0 ? (double)sppm->passes_done : 1.0;
    for (size_t k = 0; k < (size_t)sppm->kept.out_width * (size_t)sppm->kept.out_height; k++) {
        size_t i = kept_pixel(&sppm->kept, k);
        const struct progressive_estimate *e = &sppm->shared[i];
        struct vec3 photons = ppm_radiance(e->tau, e->radius, n_emitted);
        struct vec3 l = vec3_add(vec3_scale(sppm->emission_seen[i], 1.0 / passes),
                                 vec3_scale(photons, 1.0 / covered_share(sppm, i)));
        if (sppm->ps->progressive.direct_light_samples)
            l = vec3_add(l, ppm_direct_radiance(&sppm->direct, i));
        if (!vec3_is_finite(l)) { /* a bug upstream: report, never write */
            sppm->counters->nonfinite_samples++;
            l = vec3_zero();
        }
        image->pixels[k] = l;
    }
}

/* ---- the error image ---------------------------------------------------------------- */

/* --target-error's judgement (progressive.h): the image so far and its error image. */
static int target_reached(void *context, double n_emitted)
{
    struct sppm *sppm = context;
    struct image *mean = image_create(sppm->kept.out_width, sppm->kept.out_height);
    evaluate_image(sppm, n_emitted, mean);
    state_shares(sppm);
    int reached = sppm_error_target(&sppm->error, &sppm->kept, sppm->passes_done, mean,
                                    sppm->counters);
    image_free(mean);
    return reached;
}

/* ---- the passes -------------------------------------------------------------------- */

struct sppm_settings sppm_settings_default(void)
{
    struct sppm_settings ps;
    ps.progressive = ppm_settings_default().progressive;
    ps.progressive.passes = SPPM_DEFAULT_PASSES;
    ps.progressive.photons_per_pass = SPPM_DEFAULT_PHOTONS_PER_PASS;
    ps.disc_coverage = 1;
    ps.follow_glossy_lobes = 1;
    return ps;
}

struct render_result render_sppm(const struct scene *scene, const struct render_settings *rs,
                                 const struct sppm_settings *ps,
                                 struct render_counters *counters, struct ppm_stats *stats)
{
    const struct progressive_settings *common = &ps->progressive;
    struct sppm sppm;
    memset(&sppm, 0, sizeof sppm);
    memset(stats, 0, sizeof *stats);
    sppm.scene = scene;
    sppm.want_error = rs->error_confidence > 0;
    kept_window_init(&sppm.kept, rs, scene->width, scene->height,
                     sppm.want_error ? SPPM_ERROR_MARGIN : 0); /* the pixels its pools read */
    sppm.rs = &sppm.kept.grown;
    sppm.ps = ps;
    sppm.counters = counters;
    sppm.stats = stats;
    sppm.n_pixels = (size_t)sppm.kept.width * (size_t)sppm.kept.height;
    sppm.shared = xcalloc(sppm.n_pixels, sizeof *sppm.shared, "sppm statistics");
    sppm.emission_seen = xcalloc(sppm.n_pixels, sizeof *sppm.emission_seen, "sppm pixels");
    sppm.points = xmalloc(sppm.n_pixels, sizeof *sppm.points, "sppm hit points");
    if (ps->disc_coverage) {
        sppm.coverage = xcalloc(sppm.n_pixels, sizeof *sppm.coverage, "sppm disc coverage");
        sppm.fitted = xcalloc(sppm.n_pixels, sizeof *sppm.fitted, "sppm fitted planes");
    }
    sppm.photons_per_pass = (double)common->photons_per_pass;
    sppm.parts = xmalloc(scene->n_materials + 1, sizeof *sppm.parts, "sppm materials");
    for (size_t m = 0; m < scene->n_materials; m++)
        sppm.parts[m] = brdf_split(&scene->materials[m]);
    if (common->direct_light_samples)
        ppm_direct_create(&sppm.direct, scene, sppm.rs);
    if (sppm.want_error) {
        sppm_error_create(&sppm.error, &sppm.kept, BLOCK_BIAS_REACH);
        sppm.pass_photons = xmalloc(2 * sppm.n_pixels, sizeof *sppm.pass_photons,
                                    "sppm pass values");
        sppm.inner_tau = xcalloc(sppm.n_pixels, sizeof *sppm.inner_tau, "sppm inner flux");
        sppm.inner_probes = xcalloc(2 * sppm.n_pixels, sizeof *sppm.inner_probes,
                                    "sppm inner probes");
    }
    struct render_result result = {NULL, NULL, NULL, NULL, NULL, NULL, 0.0};
    result.image = image_create(sppm.kept.out_width, sppm.kept.out_height);

    /* Each pass: the distributed ray tracing pass, the photon tracing pass, the update. */
    struct progressive_steps steps = {&sppm, distributed_ray_tracing_pass, add_photon, NULL,
                                      progressive_update, evaluate_image, mean_radius,
                                      rs->target_error > 0 ? target_reached : NULL, counters};
    struct progressive_run run = progressive_passes(&steps, scene, rs, common, 0.0,
                                                    result.image, &stats->photon_rays);
    result.seconds = run.seconds;
    if (sppm.want_error) {
        clock_t start = clock();
        state_shares(&sppm);
        sppm_error_result(&sppm.error, &sppm.kept, sppm.passes_done, &result);
        result.seconds += cpu_seconds(start);
        sppm_error_free(&sppm.error);
        xfree(sppm.pass_photons);
        xfree(sppm.inner_tau);
        xfree(sppm.inner_probes);
    }
    stats->passes = run.passes;
    stats->seconds_photons = run.seconds - stats->seconds_ray_pass;
    stats->hit_points = sppm.n_points;
    stats->bytes_per_hit_point = sizeof(struct hit_point) + HIT_POINT_TREE_BYTES_PER_POINT +
                                 sizeof(struct progressive_estimate) + sizeof(struct vec3) +
                                 (ps->disc_coverage ? sizeof(struct disc_share) +
                                                          sizeof(struct fitted_plane)
                                                    : 0);
    stats->photons_emitted = run.photons_emitted;
    stats->mean_radius = mean_radius(&sppm);
    counters->passes = (int)run.passes;
    hit_point_tree_free(&sppm.tree);
    if (common->direct_light_samples)
        ppm_direct_free(&sppm.direct);
    xfree(sppm.parts);
    xfree(sppm.coverage);
    xfree(sppm.fitted);
    xfree(sppm.points);
    xfree(sppm.emission_seen);
    xfree(sppm.shared);
    return result;
}
