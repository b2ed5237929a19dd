/*
 * scene/emit.h -- where a photon leaves a light, which way it goes, and its share of the
 * light's power (Jensen 1996, Sec. 3: "emitting photons from the light sources").
 *
 * light_emit() samples each light's own emission, so that every photon of light l
 * carries the same power: with N photons emitted from l, each one carries Phi_l / N
 * (Phi_l = light_power(l)), whatever its origin and direction. The densities that make
 * this so:
 *   point light   direction uniform over the sphere (I = Phi / (4 pi) in every direction);
 *   sphere light  origin uniform by area on the sphere, direction cosine-distributed
 *                 about the outward normal (Le cos over the front hemisphere);
 *   quad and      origin uniform by area, direction cosine-distributed about the front
 *   triangle      normal e1 x e2 (the side light_sample() sees).
 *
 * light_emit_towards() is directed emission (Jensen 1996, Sec. 3: the caustic map is made
 * "by emitting photons towards the specular objects"): directions are drawn only inside
 * the cones from the origin towards a set of target bounding spheres, and the photon's
 * weight corrects for the narrower density so that the expected flux through any
 * direction in the cones is exactly the light's. Directions outside every cone are never
 * drawn: a map made this way holds only the light that first travels towards a target.
 *
 * Sampling uses only the uniform numbers it is given, so callers stay deterministic.
 */
#ifndef PHOTON_EMIT_H
#define PHOTON_EMIT_H

#include <stddef.h>

#include "light.h"

/* A sphere enclosing a target object: where directed emission aims. */
struct bounding_sphere {
    struct vec3 centre;
    double radius; /* > 0 */
};

/* The targets of directed emission: an array with its count. */
struct emission_targets {
    const struct bounding_sphere *spheres; /* borrowed; n_spheres of them */
    size_t n_spheres;                      /* >= 1                        */
};

/* One emitted photon. Of N photons emitted from light l, this one carries the power
 * Phi_l * weight / N (per channel, Phi_l = light_power(l)). */
struct emission {
    struct vec3 origin; /* on the light: the point light's position, or a point of an
                           area light's surface                                        */
    struct vec3 dir;    /* unit direction of travel                                     */
    struct vec3 normal; /* unit front normal at origin for area lights, pointing to the
                           side dir leaves on; zero for a point light (no surface)      */
    double weight;      /* 1 for light_emit(); for light_emit_towards() the emitted
                           density over the sampling density (see emit.c), >= 0, and its
                           expectation is the fraction of Phi_l sent into the cones     */
};

struct scene;

/* The targets of a caustic map's directed emission (Jensen 1996, Sec. 3: "emitting
 * photons towards the specular objects"): one sphere per material with a specular part
 * f_r,s (brdf_split(): a delta or a glossy lobe, Eq. 2's "highly glossy and ideal
 * specular") around the box of the primitives made of it. spheres has room for
 * scene->n_materials; returns how many it filled, 0 when nothing in the scene is
 * specular (then no caustic map is needed). One sphere per material rather than per
 * primitive keeps emission cheap for meshes; two far-apart objects of one material get
 * one large sphere, which costs photons, never correctness. */
size_t specular_targets(const struct scene *scene, struct bounding_sphere *spheres);

/* Emits one photon from l with four uniform numbers in [0, 1): u[0], u[1] choose the
 * origin (unused by a point light), u[2], u[3] the direction. Returns 1 and fills *e
 * (weight 1), or 0 for a light with no area (a degenerate quad or triangle). */
int light_emit(const struct light *l, const double u[4], struct emission *e);

/* Directed emission towards targets (n_spheres >= 1) with five uniform numbers: u[0],
 * u[1] the origin as light_emit(), u[2], u[3] the direction inside a target's cone, u[4]
 * which target. Returns 1 and fills *e, or 0 when no photon results (a light with no
 * area, targets too small or far to subtend a representable solid angle, or a direction
 * behind an area light's front): such a photon counts as emitted and carries nothing. */
int light_emit_towards(const struct light *l, const struct emission_targets *targets,
                       const double u[5], struct emission *e);

#endif
