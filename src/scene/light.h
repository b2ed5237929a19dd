/*
 * scene/light.h -- light sources and sampling them for direct lighting.
 *
 * Point lights are given by power Phi (watts per RGB channel, radiated uniformly, so the
 * intensity is I = Phi / (4 pi)). Area lights -- spheres, quads, triangles -- are given
 * by the radiance Le leaving their front side (a sphere's outside, the counter-clockwise
 * side of a quad or triangle); they are also geometry, seen by rays, with a black
 * reflectance when made by the `light` keyword.
 *
 * Sampling returns a direction with its pdf in solid angle: a sphere by the cone of
 * directions it subtends, a quad or triangle uniformly by area (converted to solid angle).
 */
#ifndef PHOTON_LIGHT_H
#define PHOTON_LIGHT_H

#include "../base/vec3.h"

enum light_kind { LIGHT_POINT, LIGHT_SPHERE, LIGHT_QUAD, LIGHT_TRIANGLE };

struct light {
    enum light_kind kind;
    struct vec3 position; /* point: position; sphere: centre; quad, triangle: corner v0    */
    struct vec3 e1, e2;   /* quad: edges, points v0 + s e1 + t e2; triangle: v1-v0, v2-v0 */
    double radius;        /* sphere only                                                   */
    struct vec3 power;    /* point only: Phi, W per channel                                */
    struct vec3 radiance; /* area lights: Le leaving the front side                        */
    int prim;             /* geometry id of the emitting primitive; -1 for point lights    */
};

/* One sampled direction from a shaded point towards a light. */
struct light_sample {
    struct vec3 wi;  /* unit direction from the shaded point towards the light           */
    double distance; /* to the sampled point on the light: the shadow ray's length       */
    struct vec3 li;  /* incident radiance along wi; for a point light, which is a delta,
                        the irradiance I / d^2 it gives at normal incidence               */
    double pdf;      /* solid-angle pdf of wi; 1 for a point light (a delta)             */
};

/* Samples light l as seen from point p with two uniform numbers in [0, 1). Returns 0 when
 * the light cannot illuminate p (p inside a sphere light, behind a one-sided emitter, or
 * a degenerate sample); *s is then unspecified. */
int light_sample(const struct light *l, struct vec3 p, double u1, double u2,
                 struct light_sample *s);

/* The solid-angle pdf with which light_sample() from p produces the direction wi that
 * reaches the light's front at point q (a hit on the light): what multiple importance
 * sampling needs when a BRDF-sampled ray lands on an emitter. 0 for a point light. */
double light_pdf(const struct light *l, struct vec3 p, struct vec3 q, struct vec3 wi);

/* Total emitted power Phi per channel: a point light's power; an area light of radiance
 * Le and area A emitting from one side into the hemisphere, Phi = pi Le A. */
struct vec3 light_power(const struct light *l);

#endif
