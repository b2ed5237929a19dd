/*
 * modes/ppm2008.c -- `--mode 2008`: progressive photon mapping (Hachisuka, Ogaki and
 * Jensen 2008), read top to bottom as the paper's Sec. 3.1 and 4:
 *
 *   3.1 the ray tracing pass stores a hit point wherever an eye path, followed through
 *       every mirror and glass bounce (both of glass's lobes, as standard ray tracing
 *       does; Russian roulette ends long ones), meets a surface with a non-specular part;
 *   3.1 each photon tracing pass shoots photons with the shared tracer; every photon that
 *       lands on a non-specular surface adds f_r Phi' to each hit point whose disc holds
 *       it; no photon is kept after its pass;
 *   4.1 after each pass every hit point shrinks its radius (Eq. 9), keeping alpha of the
 *       new photons (Eq. 7); 4.2 corrects its flux (Eq. 12);
 *   4.3 the image at any time: each hit point's radiance (Eq. 13) times its pixel weight,
 *       plus the emission the eye paths saw directly, which the paper does not mention.
 *
 * Each departure from the paper below has a switch; --paper turns all seven off
 * (src/modes/README.md has the figures of each).
 *
 * The direct light (--no-direct-light-samples is the paper's way). The paper estimates it
 * from the photons like all the rest; on a diffuse box it is most of the light, and so most
 * of the estimate's noise and of its blur (across a shadow's edge, at a corner). By default
 * each pass's new eye ray through each pixel (below) takes it by light sampling instead, as
 * pbrt-v4's SPPM keeps a direct term beside its photons: one shadow-tested sample of every
 * light wherever that ray meets a surface with a non-delta part (ppm_direct.c, the samples
 * of --mode direct); the pixel's direct term is the mean over the passes, so shadows and
 * the light's outline are anti-aliased like a path tracer's. A photon then adds to hit
 * points only once it has bounced: its first hit, straight from the light, is what the
 * light samples count; after mirrors and glass (L S+ D, caustics) it still adds, since a
 * shadow ray is blocked by them and never sees the light that way.
 *
 * The new eye ray each pass (--resample-emission; the paper's eye rays are traced once):
 * a light's outline would otherwise keep the aliasing of --spp rays a pixel however long
 * the render ran, and a light hundreds of times brighter than the ceiling around it moves
 * a block's mean by percents with one eye ray more or less on it. So every photon pass
 * also traces one more eye ray through each pixel (its next camera sample), which stores
 * no hit point; the emission part of a pixel is the mean over all its eye rays so far.
 *
 * Merged hit points (--merge-hit-points). With the direct light sampled, the hit points
 * carry only the photons' light, which is smooth over a disc several pixels wide: a
 * pixel's eye rays that meet the same surface within a hit point's disc add their weight
 * to it instead of making hit points of their own, whose discs would hold nearly the same
 * photons. A photon pass costs in proportion to the hit points each photon reaches, so
 * this is most of the speed; the aliasing the merge leaves (one point stands for a
 * pixel's part of a surface) is of the photons' smooth light only.
 *
 * The initial radius (--footprints, --fit-radius). R0 is PPM_DEFAULT_FOOTPRINTS widths of
 * a pixel at its hit point (the paper's "footprint of the pixel" is one; it leaves R0 to
 * the user), shortened until the disc lies on its surface (ppm_radius.c: why and how).
 *
 * The caustic estimate (--caustic-footprints K; --no-caustic-footprints is the paper's).
 * Caustic photons are sparse and their light sharp; a disc wide enough for the smooth
 * indirect light blurs them. As Jensen's caustic map has a smaller radius than his global
 * one, each hit point keeps a second estimate of caustic photons (Eq. 7-12, R0 a footprint).
 *
 * The facing test (--facing-test): a photon counts only at hit points whose surface faces
 * its own (add_flux()); Sec. 3.1 takes every photon within R, and the sphere of radius R
 * also reaches through thin walls and onto the back of the hit point's own surface. Turned
 * photon directions (--turn-photon-directions): f_r sees a photon arrive as it met its own
 * surface, so none falls below a curved one's horizon (hit_point_add_photon()).
 *
 * The error image (--error, --target-error; ppm_error.h): each pass hands every pixel's
 * pass values to 2009's batches (progressive_update()); the window kept grows by
 * SPPM_ERROR_MARGIN pixels each side, whose hit points only the error image reads
 * (evaluate_image() writes the asked window alone), so a crop's error image is its window
 * of the whole's, and the image is the same with it or without.
 *
 * Determinism: photon i of pass p draws from rng_stream(seed, STREAM_PHOTON, p, i) and eye
 * sample s of pixel (x, y) from its camera stream (render.h); the light samples of the
 * k-th surface a pixel's new eye ray meets are keyed by the pixel and k (ppm_direct.h);
 * each hit point receives its photons in photon order, and the image sums a pixel's hit
 * points in the order they were made, so a pixel depends on nothing but its own eye rays.
 */
#include "ppm2008.h"

#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../base/alloc.h"
#include "../photon/hit_points.h"
#include "../photon/trace.h"
#include "ppm_direct.h"
#include "ppm_error.h"
#include "ppm_radius.h"
#include "surface.h"

#define PPM_MERGE_COS 0.9    /* hit points merge within 26 degrees (can_stand_in())   */
#define PPM_ROULETTE_DEPTH 8 /* eye-path bounces before Russian roulette (take_lobe())  */

/* An eye ray's hit merged into (or making) hit point `point`, until its pixel is done. */
struct pending_member {
    size_t point;
    struct vec3 x;      /* where the ray met the surface */
    struct vec3 weight; /* its pixel weight              */
};

struct ppm {
    const struct scene *scene;          /* borrowed                                       */
    const struct render_settings *rs;   /* &kept.grown                                    */
    struct kept_window kept;            /* the caller's window, grown by SPPM_ERROR_MARGIN
                                           with an error image (the pixels its bound
                                           reads; sppm_error.h)                           */
    const struct ppm_settings *ps;      /* borrowed                                       */
    struct render_counters *counters;   /* borrowed                                       */
    int width, height;                  /* of the window kept                             */
    struct vec3 *emission_seen;         /* owned: per window pixel, the sum of the emission
                                           and background radiance seen along its eye rays */
    long eye_rays;                      /* eye rays per pixel in emission_seen so far:
                                           --spp, and one more each photon pass           */
    struct hit_point *points;           /* owned: n_points of cap_points, in the order made */
    size_t n_points, cap_points;
    struct hit_point_tree tree;         /* over points                                    */
    double footprint_per_distance;      /* a pixel's width at distance 1: 2 tan(fov/2) / H */
    const struct photon_event *photon;  /* the photon being added (Sec. 3.1)              */
    double photons_per_pass;            /* turns the tracer's Phi / N back into the
                                           paper's unnormalised Phi'                      */
    struct ppm_direct direct;           /* the direct term, unless the photons bring it   */
    long pass;                          /* the photon pass under way, from 0              */
    size_t pixel_first_point;           /* the first hit point of the pixel being traced    */
    int keep_members;                   /* merged hit points keep their members (below)   */
    struct pending_member *pending;     /* owned: the current pixel's eye rays' hits, each
                                           with its hit point; n_pending of cap_pending    */
    size_t n_pending, cap_pending;
    struct hit_member *members;         /* owned: every hit point's members, hit point
                                           after hit point; n_members of cap_members       */
    size_t n_members, cap_members;
    uint64_t surfaces_met;              /* surfaces with a non-delta part the current eye
                                           ray (all its branches) has met so far          */
    int want_error;                     /* rs->error_confidence > 0                       */
    struct ppm_error error;             /* with want_error (ppm_error.h)                  */
};

struct ppm_settings ppm_settings_default(void)
{
    struct ppm_settings ps;
    ps.progressive.photons_per_pass = PPM_DEFAULT_PHOTONS_PER_PASS;
    ps.progressive.passes = PPM_DEFAULT_PASSES;
    ps.progressive.alpha = PPM_DEFAULT_ALPHA;
    ps.progressive.radius = 0.0;
    ps.progressive.footprints = PPM_DEFAULT_FOOTPRINTS;
    ps.progressive.fit_radius = 1;
    ps.progressive.facing_test = 1;
    ps.progressive.turn_photon_directions = 1;
    ps.progressive.direct_light_samples = 1;
    ps.progressive.report = NULL;
    ps.progressive.snapshot_every = 0;
    ps.progressive.snapshot = NULL;
    ps.merge_hit_points = 1;
    ps.resample_emission = 1;
    ps.caustic_footprints = PPM_DEFAULT_CAUSTIC_FOOTPRINTS;
    ps.observer = NULL;
    return ps;
}

/* ---- 3.1 The ray tracing pass ------------------------------------------------------- */

/* An eye path so far: whose it is, what it carries and how far it has come. */
struct eye_path {
    size_t pixel;     /* row-major index in the window                 */
    struct vec3 beta; /* throughput of the mirror and glass bounces    */
    double distance;  /* length travelled from the camera              */
    int depth;        /* mirror and glass bounces so far               */
};

/* What an eye ray does at each surface with a non-delta part it meets: in the ray tracing
 * pass, store a hit point (store_hit_point()); along each pass's new eye ray, a departure,
 * take the direct light's samples (take_light_samples()). */
typedef void at_surface_fn(struct ppm *ppm, const struct surface *s,
                           const struct shading_frame *frame, const struct eye_path *path);

/* R0 of a hit point's caustic estimate, whose global one starts at global_r0: --radius
 * if given; else ps->caustic_footprints footprints, at most global_r0 when that was fitted
 * to the surface (a smaller disc lies on it too); 0 (no caustic estimate: caustic photons
 * go to the global one) when ps->caustic_footprints is 0. */
static double caustic_radius(const struct ppm *ppm, double global_r0, double distance)
{
    const struct ppm_settings *ps = ppm->ps;
    if (ps->caustic_footprints <= 0)
        return 0.0;
    if (ps->progressive.radius > 0)
        return ps->progressive.radius;
    double r0 = ps->caustic_footprints * distance * ppm->footprint_per_distance;
    return ps->progressive.fit_radius ? fmin(r0, global_r0) : r0;
}

static struct progressive_estimate empty_estimate(double radius)
{
    struct progressive_estimate e = {radius, 0.0, {0.0, 0.0, 0.0}, 0};
    return e;
}

/* Whether a hit point at s with outgoing direction s->wo can stand in for hp, of the same
 * pixel: the same material, within hp's disc, facing and seen the same way to within
 * PPM_MERGE_COS. Photons then reach both alike, and Eq. 13 at hp, a footprint or less
 * away inside a disc several footprints wide, is the estimate the new one would make. */
static int can_stand_in(const struct hit_point *hp, const struct surface *s)
{
    return hp->material == s->material &&
           vec3_length2(vec3_sub(hp->x, s->p)) <= hp->global.radius * hp->global.radius &&
           vec3_dot(hp->n, s->ng) >= PPM_MERGE_COS && vec3_dot(hp->wo, s->wo) >= PPM_MERGE_COS;
}

/* Merged hit points keep their members (--merge-hit-points with the caustic estimate, in a
 * scene with something specular to make caustics). The hit point stands for its members'
 * part of the surface at one point: right for the photons' smooth light after a bounce,
 * not for a caustic seen directly, whose sharp light a single point aliases (the specular
 * box's caustic under the glass ball: src/modes/README.md). So the caustic estimate is the
 * mean over the members' own discs, sharing one radius: a caustic photon counts by the
 * share of members whose disc holds it (hit_point_add_photon()), and as the radius shrinks
 * the estimate tends to the mean of the members' points, as the paper's hit points do. */
static void add_member(struct ppm *ppm, size_t point, struct vec3 x, struct vec3 weight)
{
    if (ppm->n_pending == ppm->cap_pending) {
        ppm->cap_pending = ppm->cap_pending > 0 ? 2 * ppm->cap_pending : 64;
        ppm->pending = xrealloc(ppm->pending, ppm->cap_pending, sizeof *ppm->pending,
                                "hit point members");
    }
    struct pending_member *m = &ppm->pending[ppm->n_pending++];
    m->point = point;
    m->x = x;
    m->weight = weight;
}

/* At the end of a pixel: each of its hit points that stands for two eye rays or more
 * keeps them as members, one after another in ppm->members (their pointers are set once
 * the array is whole, members_in_place()). */
static void keep_pixel_members(struct ppm *ppm)
{
    for (size_t i = ppm->pixel_first_point; i < ppm->n_points; i++) {
        struct hit_point *hp = &ppm->points[i];
        double total = 0.0;
        uint32_t n = 0;
        for (size_t k = 0; k < ppm->n_pending; k++)
            if (ppm->pending[k].point == i) {
                total += vec3_luminance(ppm->pending[k].weight);
                n++;
            }
        if (n < 2)
            continue;
        for (size_t k = 0; k < ppm->n_pending; k++) {
            const struct pending_member *p = &ppm->pending[k];
            if (p->point != i)
                continue;
            if (ppm->n_members == ppm->cap_members) {
                ppm->cap_members = ppm->cap_members > 0 ? 2 * ppm->cap_members : 4096;
                ppm->members = xrealloc(ppm->members, ppm->cap_members, sizeof *ppm->members,
                                        "hit point members");
            }
            struct vec3 offset = vec3_sub(p->x, hp->x);
            struct hit_member *m = &ppm->members[ppm->n_members++];
            m->dx = (float)offset.x;
            m->dy = (float)offset.y;
            m->dz = (float)offset.z;
            m->share = (float)(total > 0 ? vec3_luminance(p->weight) / total : 1.0 / n);
            hp->spread = fmax(hp->spread, vec3_length(offset));
        }
        hp->n_members = n;
    }
    ppm->n_pending = 0;
}

/* Points every hit point with members at its own, now that ppm->members is whole. */
static void members_in_place(struct ppm *ppm)
{
    size_t first = 0;
    for (size_t i = 0; i < ppm->n_points; i++)
        if (ppm->points[i].n_members > 0) {
            ppm->points[i].members = ppm->members + first;
            first += ppm->points[i].n_members;
        }
}

/* Whether scene can make caustics: some material has a delta lobe. */
static int makes_caustics(const struct scene *scene)
{
    for (size_t i = 0; i < scene->n_materials; i++)
        if (brdf_has_delta(&scene->materials[i]))
            return 1;
    return 0;
}

/* The merge (--merge-hit-points, a departure): adds weight, an eye ray's at s, to a hit
 * point of the pixel that can stand in for one at s; returns 0 when none can. */
static int merged_into_pixel_point(struct ppm *ppm, const struct surface *s,
                                   struct vec3 weight)
{
    for (size_t i = ppm->pixel_first_point; i < ppm->n_points; i++)
        if (can_stand_in(&ppm->points[i], s)) {
            ppm->points[i].weight = vec3_add(ppm->points[i].weight, weight);
            if (ppm->keep_members)
                add_member(ppm, i, s->p, weight);
            return 1;
        }
    return 0;
}

/* Sec. 3.1: stores a hit point at s, reached by the eye path (unless merged). */
static void store_hit_point(struct ppm *ppm, const struct surface *s,
                            const struct shading_frame *frame, const struct eye_path *path)
{
    struct vec3 weight = vec3_scale(path->beta, 1.0 / ppm->rs->spp); /* the box filter's share */
    if (ppm->ps->merge_hit_points && merged_into_pixel_point(ppm, s, weight))
        return;
    if (ppm->n_points == ppm->cap_points) {
        ppm->cap_points = ppm->cap_points > 0 ? 2 * ppm->cap_points : 4096;
        ppm->points = xrealloc(ppm->points, ppm->cap_points, sizeof *ppm->points,
                               "hit points");
    }
    struct hit_point *hp = &ppm->points[ppm->n_points++];
    hp->x = s->p;
    hp->n = s->ng;
    hp->wo = s->wo;
    hp->frame = *frame;
    hp->material = s->material;
    hp->pixel = path->pixel;
    hp->weight = weight;
    hp->global = empty_estimate(ppm_initial_radius(ppm->scene, &ppm->ps->progressive, 0,
                                                   ppm->counters, s, path->distance));
    hp->caustic = empty_estimate(caustic_radius(ppm, hp->global.radius, path->distance));
    hp->members = NULL;
    hp->n_members = 0;
    hp->spread = 0.0;
    if (ppm->keep_members)
        add_member(ppm, ppm->n_points - 1, s->p, weight);
}

/* The specular directions an eye path follows from s into lobes[]; returns how many. Sec.
 * 3.1 finds the surfaces "using standard ray tracing": a mirror's reflection, and glass's
 * reflection and refraction both (Whitted), each with its reflectance as weight, so what is
 * seen through glass carries no noise from choosing between them. A material with a
 * non-specular part beside a mirror lobe (Schlick with r < 1/2) has its one sampled
 * direction followed when it is the mirror's, as a path tracer would. */
static int specular_lobes(const struct surface *s, const struct shading_frame *frame,
                          struct rng *rng, struct brdf_sample lobes[2])
{
    if (brdf_is_delta(s->material))
        return brdf_delta_lobes(s->material, frame, s->wo, lobes);
    if (!brdf_has_delta(s->material))
        return 0;
    double u[3];
    rng_uniforms(rng, u, 3);
    return brdf_sample(s->material, frame, s->wo, u, &lobes[0]) && lobes[0].delta;
}

/* Turns the eye path at s into lobe: throughput times the lobe's weight, one bounce more,
 * Russian roulette (surface.h) once the path has made PPM_ROULETTE_DEPTH bounces. Returns
 * 0 when roulette ends it; else *ray is the ray leaving s along the lobe. Roulette waits
 * longer here than in a path tracer because a hit point is made once for the whole
 * render: its roulette decision is frozen into every pass, keeping a low-weight path at
 * weight 1/q or losing it for good, which no number of passes averages out (with
 * roulette from the third bounce the glass ball seen in the mirror ball is dark on
 * average over seeds: src/modes/README.md). Paths that long weigh next to nothing after
 * mirrors and glass. */
static int take_lobe(const struct surface *s, const struct brdf_sample *lobe,
                     struct eye_path *path, struct rng *rng, struct ray *ray)
{
    path->beta = vec3_mul(path->beta, lobe->weight);
    path->depth++;
    if (path->depth >= PPM_ROULETTE_DEPTH && !survives_roulette(&path->beta, path->depth, rng))
        return 0;
    *ray = surface_ray(s, lobe->wi, lobe->transmitted);
    return 1;
}

static struct vec3 follow_eye_ray(struct ppm *ppm, struct ray ray, struct eye_path path,
                                  at_surface_fn *at_surface, struct rng *rng);

/* The emission seen along lobe from s by an eye path of its own (a copy of path). */
static struct vec3 follow_lobe(struct ppm *ppm, const struct surface *s,
                               const struct brdf_sample *lobe, struct eye_path path,
                               at_surface_fn *at_surface, struct rng *rng)
{
    struct ray ray;
    if (!take_lobe(s, lobe, &path, rng, &ray))
        return vec3_zero();
    return follow_eye_ray(ppm, ray, path, at_surface, rng);
}

/* Follows an eye ray through mirrors and glass (every lobe; Russian roulette on long
 * chains), calling at_surface at every surface with a non-specular part. Returns the
 * emission and background radiance seen along the way, which goes to the pixel directly.
 * Glass's first lobes get paths of their own (recursion) and its last one continues this
 * loop, so a chain of mirrors costs no stack. */
static struct vec3 follow_eye_ray(struct ppm *ppm, struct ray ray, struct eye_path path,
                                  at_surface_fn *at_surface, struct rng *rng)
{
    struct vec3 emission = vec3_zero();
    for (;;) {
        struct surface s;
        double t;
        if (!ray_surface(ppm->scene, ray, ppm->counters, &s, &t))
            return vec3_add(emission, vec3_mul(path.beta, ppm->scene->background));
        path.distance += t;
        struct shading_frame frame = shading_frame_from_normal(s.ns, s.front,
                                                               TRANSPORT_RADIANCE);
        emission = vec3_add(emission, vec3_mul(path.beta, surface_emission(&s)));
        if (brdf_has_non_delta(s.material))
            at_surface(ppm, &s, &frame, &path);
        struct brdf_sample lobes[2];
        int n = path.depth < ppm->rs->max_depth ? specular_lobes(&s, &frame, rng, lobes) : 0;
        for (int k = 0; k + 1 < n; k++)
            emission = vec3_add(emission, follow_lobe(ppm, &s, &lobes[k], path, at_surface,
                                                      rng));
        if (n == 0 || !take_lobe(&s, &lobes[n - 1], &path, rng, &ray))
            return emission;
    }
}

/* Row-major index of image pixel (x, y) in the window. */
static size_t window_pixel(const struct ppm *ppm, int x, int y)
{
    const struct render_settings *rs = ppm->rs;
    return (size_t)(y - rs->y0) * (size_t)ppm->width + (size_t)(x - rs->x0);
}

/* Eye ray `sample` through pixel (x, y) (camera_sample(), stratified over any run of
 * samples from 0), followed by follow_eye_ray(); returns the emission it saw. */
static struct vec3 eye_ray(struct ppm *ppm, int x, int y, int sample, at_surface_fn *at_surface)
{
    struct rng rng;
    struct ray ray = camera_sample(ppm->scene, ppm->rs->seed, x, y, sample, &rng);
    struct eye_path path = {window_pixel(ppm, x, y), vec3(1.0, 1.0, 1.0), 0.0, 0};
    ppm->surfaces_met = 0;
    return follow_eye_ray(ppm, ray, path, at_surface, &rng);
}

/* rs->spp eye rays through every pixel, storing hit points and adding the emission each
 * sees to the pixel's sum, then the hit points' tree. */
static void ray_tracing_pass(struct ppm *ppm)
{
    const struct render_settings *rs = ppm->rs;
    for (int y = rs->y0; y < rs->y1; y++)
        for (int x = rs->x0; x < rs->x1; x++) {
            struct vec3 *emission = &ppm->emission_seen[window_pixel(ppm, x, y)];
            ppm->pixel_first_point = ppm->n_points;
            for (int s = 0; s < rs->spp; s++)
                *emission = vec3_add(*emission, eye_ray(ppm, x, y, s, store_hit_point));
            if (ppm->keep_members)
                keep_pixel_members(ppm);
        }
    ppm->eye_rays = rs->spp;
    members_in_place(ppm);
    hit_point_tree_build(&ppm->tree, ppm->points, ppm->n_points);
}

/* ---- 3.1 Photon tracing passes ------------------------------------------------------ */

/* A photon within reach of hit point i: Eq. 11 for the estimate it belongs to
 * (hit_point_add_photon()): the caustic one for a caustic photon, if the hit points
 * keep one. */
static void add_flux(void *context, size_t i)
{
    struct ppm *ppm = context;
    const struct progressive_settings *p = &ppm->ps->progressive;
    hit_point_add_photon(&ppm->points[i], ppm->photon, ppm->photons_per_pass, p->facing_test,
                         p->turn_photon_directions, ppm->ps->caustic_footprints > 0,
                         ppm->want_error ? &ppm->error.inner[2 * i] : NULL);
}

/* Each photon a photon tracing pass stores goes to the hit points around it, at every
 * non-specular hit (direct, caustic and indirect alike) with --no-direct-light-samples; by
 * default except the first hit straight from the light. Departs from Sec. 3.1 there: the
 * light samples of ppm_direct.c bring that light (the departure at the top). */
static void add_photon(void *context, const struct photon_event *photon)
{
    struct ppm *ppm = context;
    ppm->photon = photon;
    hit_point_tree_visit(&ppm->tree, photon->position, add_flux, ppm);
}

/* Along each pass's new eye ray (a departure): one sample of every light at s, unless the
 * photons bring the direct light. */
static void take_light_samples(struct ppm *ppm, const struct surface *s,
                               const struct shading_frame *frame, const struct eye_path *path)
{
    if (ppm->ps->progressive.direct_light_samples)
        ppm_direct_sample(&ppm->direct, path->pixel, ppm->surfaces_met++, ppm->pass, s, frame,
                          path->beta, ppm->counters);
}

/* After photon pass p (from 0), one more eye ray through every pixel that takes the direct
 * light, unless the photons bring it, and adds the emission it sees, unless only the ray
 * tracing pass's rays do (the departures explained at the top). */
static void eye_ray_pass(void *context, long pass)
{
    struct ppm *ppm = context;
    const struct render_settings *rs = ppm->rs;
    int direct_light_samples = ppm->ps->progressive.direct_light_samples;
    int resample_emission = ppm->ps->resample_emission;
    if (!direct_light_samples && !resample_emission)
        return; /* the paper's way: the ray would bring nothing */
    ppm->pass = pass;
    for (int y = rs->y0; y < rs->y1; y++)
        for (int x = rs->x0; x < rs->x1; x++) {
            struct vec3 emission = eye_ray(ppm, x, y, rs->spp + (int)pass, take_light_samples);
            size_t pixel = window_pixel(ppm, x, y);
            if (resample_emission)
                ppm->emission_seen[pixel] = vec3_add(ppm->emission_seen[pixel], emission);
        }
    if (resample_emission)
        ppm->eye_rays++;
    if (direct_light_samples)
        ppm_direct_end_pass(&ppm->direct);
}

/* ---- 4.1, 4.2 Radius reduction and flux correction ---------------------------------- */

double ppm_accumulated_photons(double n, double m, double alpha)
{
    return n + alpha * m; /* Eq. 7: N^ = N + alpha M */
}

double ppm_reduced_radius(double r, double n, double m, double alpha)
{
    if (!(n + m > 0))
        return r; /* no photon yet: nothing to trade the radius for */
    return r * sqrt((n + alpha * m) / (n + m)); /* Eq. 9: R^ = R sqrt((N + aM) / (N + M)) */
}

struct vec3 ppm_corrected_flux(struct vec3 tau_n_plus_m, double n, double m, double alpha)
{
    if (!(n + m > 0))
        return tau_n_plus_m;
    /* Eq. 12: tau^ = (tau_N + tau_M) (N + aM) / (N + M), the flux of the smaller disc */
    return vec3_scale(tau_n_plus_m, (n + alpha * m) / (n + m));
}

/* After a pass: Eq. 12, Eq. 9 and Eq. 7, in that order, since all three use the N and M
 * of the pass that just ended. */
void ppm_update_estimate(struct progressive_estimate *e, double alpha)
{
    double m = (double)e->m_photons;
    e->tau = ppm_corrected_flux(e->tau, e->n_photons, m, alpha);
    e->radius = ppm_reduced_radius(e->radius, e->n_photons, m, alpha);
    e->n_photons = ppm_accumulated_photons(e->n_photons, m, alpha);
    e->m_photons = 0;
}

/* Pass p's end: with an error image the pass values (the pass's tau_M, before Eq. 12
 * takes it), then every hit point's estimates updated (the error image keeps their tau,
 * which the next pass's tau_M adds to), then shown to the observer. */
static void progressive_update(void *context, long pass)
{
    struct ppm *ppm = context;
    double alpha = ppm->ps->progressive.alpha;
    if (ppm->want_error)
        ppm_error_add_pass(&ppm->error, &ppm->tree, ppm->photons_per_pass, ppm->emission_seen,
                           ppm->ps->progressive.direct_light_samples ? &ppm->direct : NULL);
    for (size_t i = 0; i < ppm->n_points; i++) {
        ppm_update_estimate(&ppm->points[i].global, alpha);
        ppm_update_estimate(&ppm->points[i].caustic, alpha);
    }
    if (ppm->want_error)
        ppm_error_end_pass(&ppm->error, &ppm->tree);
    hit_point_tree_refit(&ppm->tree); /* the discs shrank: tighten the boxes */
    const struct ppm_observer *observer = ppm->ps->observer;
    if (observer != NULL)
        observer->after_pass(observer->context, pass + 1, ppm->points, ppm->n_points);
}

/* ---- 4.3 Radiance evaluation --------------------------------------------------------- */

struct vec3 ppm_radiance(struct vec3 tau, double r, double n_emitted)
{
    /* Below DBL_MIN, r^2 would lose its digits; no photon can be that close anyway. */
    if (!(r * r >= DBL_MIN) || !(n_emitted > 0))
        return vec3_zero();
    return vec3_scale(tau, 1.0 / (PI * r * r * n_emitted)); /* Eq. 13 */
}

/* The image so far, of the written window: the mean of what the eye rays saw directly
 * plus every hit point's Eq. 13 radiance times its pixel weight, summed in the order the
 * hit points were made (not the tree's, which depends on the window). */
static void evaluate_image(const void *context, double n_emitted, struct image *image)
{
    const struct ppm *ppm = context;
    size_t n_pixels = (size_t)image->width * (size_t)image->height;
    for (size_t k = 0; k < n_pixels; k++) {
        size_t i = kept_pixel(&ppm->kept, k);
        image->pixels[k] = vec3_scale(ppm->emission_seen[i], 1.0 / (double)ppm->eye_rays);
        if (ppm->ps->progressive.direct_light_samples)
            image->pixels[k] = vec3_add(image->pixels[k], ppm_direct_radiance(&ppm->direct, i));
    }
    for (size_t i = 0; i < ppm->n_points; i++) {
        const struct hit_point *hp = &ppm->points[ppm->tree.place[i]]; /* the i-th made */
        size_t k = written_pixel(&ppm->kept, hp->pixel);
        if (k == NOT_WRITTEN)
            continue; /* the margin's, which only the error image reads */
        struct vec3 l = vec3_add(ppm_radiance(hp->global.tau, hp->global.radius, n_emitted),
                                 ppm_radiance(hp->caustic.tau, hp->caustic.radius, n_emitted));
        image->pixels[k] = vec3_add(image->pixels[k], vec3_mul(hp->weight, l));
    }
    for (size_t k = 0; k < n_pixels; k++)
        if (!vec3_is_finite(image->pixels[k])) { /* a bug upstream: report, never write */
            ppm->counters->nonfinite_samples++;
            image->pixels[k] = vec3_zero();
        }
}

/* --target-error's judgement (progressive.h): the image so far and its error image. */
static int target_reached(void *context, double n_emitted)
{
    struct ppm *ppm = context;
    struct image *mean = image_create(ppm->kept.out_width, ppm->kept.out_height);
    evaluate_image(ppm, n_emitted, mean);
    int reached = ppm_error_target(&ppm->error, mean, ppm->counters);
    image_free(mean);
    return reached;
}

/* ---- the passes ------------------------------------------------------------------ */

/* The mean R of the written pixels' hit points: the progress line's and --stats's. */
static double mean_radius(const void *context)
{
    const struct ppm *ppm = context;
    double sum = 0.0, n = 0.0;
    for (size_t i = 0; i < ppm->n_points; i++)
        if (written_pixel(&ppm->kept, ppm->points[i].pixel) != NOT_WRITTEN) {
            sum += ppm->points[i].global.radius;
            n++;
        }
    return n > 0 ? sum / n : 0.0;
}

struct render_result render_ppm(const struct scene *scene, const struct render_settings *rs,
                                const struct ppm_settings *ps,
                                struct render_counters *counters, struct ppm_stats *stats)
{
    const struct progressive_settings *common = &ps->progressive;
    struct ppm ppm;
    memset(&ppm, 0, sizeof ppm);
    memset(stats, 0, sizeof *stats);
    ppm.scene = scene;
    ppm.want_error = rs->error_confidence > 0;
    kept_window_init(&ppm.kept, rs, scene->width, scene->height,
                     ppm.want_error ? SPPM_ERROR_MARGIN : 0);
    ppm.rs = &ppm.kept.grown;
    ppm.ps = ps;
    ppm.counters = counters;
    ppm.width = ppm.kept.width;
    ppm.height = ppm.kept.height;
    ppm.emission_seen = xcalloc((size_t)ppm.width * (size_t)ppm.height,
                                sizeof *ppm.emission_seen, "ppm pixels");
    ppm.footprint_per_distance = camera_footprint(&scene->camera);
    ppm.photons_per_pass = (double)common->photons_per_pass;
    ppm.keep_members = ps->merge_hit_points && ps->caustic_footprints > 0 &&
                       makes_caustics(scene);
    if (common->direct_light_samples)
        ppm_direct_create(&ppm.direct, scene, ppm.rs);
    clock_t start = clock();
    ray_tracing_pass(&ppm);
    stats->seconds_ray_pass = cpu_seconds(start);
    stats->hit_points = ppm.n_points;
    stats->bytes_per_hit_point = sizeof(struct hit_point) + HIT_POINT_TREE_BYTES_PER_POINT;
    stats->hit_members = ppm.n_members;
    stats->initial_mean_radius = mean_radius(&ppm);
    if (ppm.want_error)
        ppm_error_create(&ppm.error, &ppm.kept, ppm.n_points, ppm.emission_seen,
                         common->direct_light_samples ? &ppm.direct : NULL);
    struct render_result result = {NULL, NULL, NULL, NULL, NULL, NULL, 0.0};
    result.image = image_create(ppm.kept.out_width, ppm.kept.out_height);

    /* The photon tracing passes, each followed by the new eye ray a pixel. */
    struct progressive_steps steps = {&ppm, NULL, add_photon, eye_ray_pass, progressive_update,
                                      evaluate_image, mean_radius,
                                      rs->target_error > 0 ? target_reached : NULL, counters};
    struct progressive_run run = progressive_passes(&steps, scene, rs, common,
                                                    stats->seconds_ray_pass, result.image,
                                                    &stats->photon_rays);
    stats->passes = run.passes;
    stats->seconds_photons = run.seconds;
    result.seconds = stats->seconds_ray_pass + stats->seconds_photons;
    if (ppm.want_error)
        result.seconds += ppm_error_finish(&ppm.error, &result);
    stats->photons_emitted = run.photons_emitted;
    stats->mean_radius = mean_radius(&ppm);
    counters->passes = rs->spp;
    hit_point_tree_free(&ppm.tree);
    if (common->direct_light_samples)
        ppm_direct_free(&ppm.direct);
    xfree(ppm.members);
    xfree(ppm.pending);
    xfree(ppm.points);
    xfree(ppm.emission_seen);
    return result;
}

int ppm_glossy_material(const struct scene *scene)
{
    for (size_t i = 0; i < scene->n_materials; i++) {
        struct brdf_split split = brdf_split(&scene->materials[i]);
        if (split.has_specular && !brdf_is_delta(&split.specular))
            return (int)i;
    }
    return -1;
}
