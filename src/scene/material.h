/*
 * scene/material.h -- named materials: what a surface does with light.
 *
 * A material is a plain record; scene/brdf.c evaluates it. Emission is separate from
 * reflection: any material may also emit radiance Le from the front side of the surface
 * it is on (a sphere's outside, the counter-clockwise side of a triangle or quad).
 */
#ifndef PHOTON_MATERIAL_H
#define PHOTON_MATERIAL_H

#include "../base/vec3.h"

#define MATERIAL_NAME_MAX 64 /* longest material name, including the terminating NUL */

enum material_kind {
    MATERIAL_LAMBERT, /* f_r = rho / pi                                          */
    MATERIAL_MIRROR,  /* ideal specular reflection scaled by a reflectance       */
    MATERIAL_GLASS    /* smooth dielectric: exact Fresnel, refraction, total internal reflection */
};

struct material {
    char name[MATERIAL_NAME_MAX];
    enum material_kind kind;
    struct vec3 rho;      /* Lambert: albedo rho; mirror: reflectance; glass: unused  */
    double ior;           /* glass: index of refraction inside / outside (> 0)       */
    struct vec3 emission; /* Le, radiance leaving the front side; zero if it does not emit */
};

static inline int material_emits(const struct material *m)
{
    return m->emission.x > 0 || m->emission.y > 0 || m->emission.z > 0;
}

/* Whether the material scatters only in ideal specular directions (no diffuse part). */
static inline int material_is_specular(const struct material *m)
{
    return m->kind == MATERIAL_MIRROR || m->kind == MATERIAL_GLASS;
}

#endif
