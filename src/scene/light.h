/*
 * scene/light.h -- light sources and sampling them for direct lighting.
 *
 * Point lights are given by power Phi (watts per RGB channel, radiated uniformly, so the
 * intensity is I = Phi / (4 pi)). Area lights -- spheres, quads, triangles -- are given
 * by the radiance Le leaving their front side (a sphere's outside, the counter-clockwise
 * side of a quad or triangle), and their back too when two-sided; they are also geometry,
 * seen by rays, with a black reflectance when made by the `light` keyword.
 *
 * The sky is the scene's background seen as a light: rays that leave the scene see its
 * constant radiance Le from every direction, so it lights the scene as an environment
 * light, in every mode (scene_add_sky(), scene.h). Its geometry is the scene's bounding
 * sphere (centre, radius R), through which all of its light that can meet the scene
 * enters: the power Phi = Le pi R^2 4 pi crosses it (the flux through a disc of area
 * pi R^2 facing each of the 4 pi steradians of directions), which is what photons carry
 * (emit.c) and what picking lights by power weighs.
 *
 * Sampling returns a direction with its pdf in solid angle: a sphere by the cone of
 * directions it subtends, a quad or triangle uniformly by area (converted to solid
 * angle), the sky by the cosine about the shaded point's normal (the irradiance's own
 * weight, so a surface under an open sky gets it without noise).
 */
#ifndef PHOTON_LIGHT_H
#define PHOTON_LIGHT_H

#include "../base/vec3.h"

enum light_kind { LIGHT_POINT, LIGHT_SPHERE, LIGHT_QUAD, LIGHT_TRIANGLE, LIGHT_SKY };

struct light {
    enum light_kind kind;
    struct vec3 position; /* point: position; sphere: centre; quad, triangle: corner v0;
                             sky: the centre of the scene's bounding sphere              */
    struct vec3 e1, e2;   /* quad: edges, points v0 + s e1 + t e2; triangle: v1-v0, v2-v0 */
    double radius;        /* sphere; sky: the radius R of the scene's bounding sphere    */
    struct vec3 power;    /* point only: Phi, W per channel                                */
    struct vec3 radiance; /* area lights: Le leaving the front side; sky: its Le          */
    int prim;             /* geometry id of the emitting primitive; -1 for point lights
                             and the sky, which are no geometry                          */
    int two_sided;        /* area lights: 1 when the back emits Le too (a material's
                             `twosided`): a sphere's inside, a quad's or triangle's back  */
};

/* One sampled direction from a shaded point towards a light. */
struct light_sample {
    struct vec3 wi;  /* unit direction from the shaded point towards the light           */
    double distance; /* to the sampled point on the light: the shadow ray's length;
                        INFINITY for the sky                                              */
    struct vec3 li;  /* incident radiance along wi; for a point light, which is a delta,
                        the irradiance I / d^2 it gives at normal incidence               */
    double pdf;      /* solid-angle pdf of wi; 1 for a point light (a delta)             */
};

/* Samples light l as seen from point p, whose unit normal on the side it is lit from is
 * n, with two uniform numbers in [0, 1). Returns 0 when the light cannot illuminate p (p
 * inside a sphere light, behind a one-sided emitter, or a degenerate sample); *s is then
 * unspecified. Only the sky reads n: it samples the hemisphere about n, pdf cos / pi. */
int light_sample(const struct light *l, struct vec3 p, struct vec3 n, double u1, double u2,
                 struct light_sample *s);

/* The solid-angle pdf with which light_sample() from p (normal n) produces the direction
 * wi that reaches the light's front at point q (a hit on the light; for the sky, a ray
 * that leaves the scene, q unused): what multiple importance sampling needs when a
 * BRDF-sampled ray finds a light. 0 for a point light. */
double light_pdf(const struct light *l, struct vec3 p, struct vec3 n, struct vec3 q,
                 struct vec3 wi);

/* Total emitted power Phi per channel: a point light's power; an area light of radiance
 * Le and area A emitting from one side into the hemisphere, Phi = pi Le A (twice that
 * when two-sided); the sky's Le pi R^2 4 pi (above). */
struct vec3 light_power(const struct light *l);

#endif
