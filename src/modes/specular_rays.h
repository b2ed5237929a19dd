/*
 * modes/specular_rays.h -- the specular part f_r,s of a BRDF (a mirror, glass, a glossy
 * lobe) by recursive ray tracing, as modes 1994 (L_r,s) and 1996 (Eq. 2's second term)
 * both compute it: which directions leave the part and Russian roulette on each. What a
 * path carries after the bounce (its emission rule, how the next surface is evaluated)
 * is each mode's own, so the mode gives that step as a callback.
 */
#ifndef PHOTON_SPECULAR_RAYS_H
#define PHOTON_SPECULAR_RAYS_H

#include "surface.h"

/* A mode's step along one direction bs out of the specular part at s: incoming() returns
 * the radiance arriving along bs->wi, found by the mode's path after the bounce, whose
 * throughput is the arriving path's times bs->weight times scale (the direction's share
 * of the estimate over roulette's odds). several: bs is one of several directions
 * sampled, so the path branches. */
struct specular_step {
    struct vec3 (*incoming)(const struct specular_step *step, const struct brdf_sample *bs,
                            double scale, int several);
    const void *mode;                 /* borrowed; the mode's state, for incoming()      */
    const void *path;                 /* borrowed; the mode's path arriving at s         */
    const struct surface *s;          /* where the directions leave                      */
    struct rng *rng;                  /* the camera sample's stream                      */
    struct render_counters *counters; /* the rays cast                                   */
};

/* The radiance the specular part m reflects towards step->s->wo at frame, for a path of
 * throughput beta after depth bounces. With every_lobe and m ideal (brdf_is_delta()):
 * the sum over its lobes, each with share 1, as Whitted's ray tracer follows reflection
 * and refraction both, so glass shows no noise from choosing between them. Else the
 * mean of n_rays >= 1 directions sampled from the BRDF (importance sampling), each with
 * share 1 / n_rays. A direction of weight w survives Russian roulette with odds
 * roulette_odds(beta w, depth) = q (a number is drawn only when q < 1) and then brings
 * w (share / q) times step's radiance, else nothing. Numbers are drawn from step->rng in
 * the order the directions are followed, each direction's before its step's. */
struct vec3 specular_rays(const struct material *m, const struct shading_frame *frame,
                          int every_lobe, int n_rays, struct vec3 beta, int depth,
                          const struct specular_step *step);

#endif
