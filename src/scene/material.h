/*
 * scene/material.h -- named materials: what a surface does with light.
 *
 * A material is a plain record; scene/brdf.c evaluates it. Emission is separate from
 * reflection: any material may also emit radiance Le from the front side of the surface
 * it is on (a sphere's outside, the counter-clockwise side of a triangle or quad), or
 * from both sides when two_sided is set. Light sampling covers the front side only; the
 * back side's light is found by paths that hit it (so only path tracing sees it whole).
 */
#ifndef PHOTON_MATERIAL_H
#define PHOTON_MATERIAL_H

#include "../base/vec3.h"

#define MATERIAL_NAME_MAX 64 /* longest material name, including the terminating NUL */

/* The reflection models; scene/brdf.h gives each one's formula and its citation. */
enum material_kind {
    MATERIAL_LAMBERT, /* f_r = rho / pi                                          */
    MATERIAL_MIRROR,  /* ideal specular reflection scaled by a reflectance       */
    MATERIAL_GLASS,   /* smooth dielectric: exact Fresnel, refraction, total internal
                         reflection, and an optional colour filter on refraction       */
    MATERIAL_PHONG,   /* energy-conserving modified Phong (Lafortune & Willems 1994)  */
    MATERIAL_WARD,    /* Ward's anisotropic model (1992), bounded-albedo normalisation */
    MATERIAL_SCHLICK  /* Schlick's single-slope model (1994), roughness r, isotropy p  */
};

/* Fields a kind does not use stay zero (the parser starts from memset 0). Reflectances are
 * per RGB channel in [0, 1]; the sums named below must not exceed 1 in any channel, which
 * keeps every model energy conserving (the parser refuses more; scene/brdf.c asserts). */
struct material {
    char name[MATERIAL_NAME_MAX];
    enum material_kind kind;
    struct vec3 rho;      /* Lambert: albedo rho; mirror: reflectance; glass: unused;
                             Phong: diffuse kd; Ward: diffuse rho_d; Schlick: colour C  */
    double ior;           /* glass: index of refraction inside / outside (> 0)       */
    struct vec3 absorption; /* glass: the fraction of each channel absorbed at each
                             refraction, in [0, 1]; 0 is clear glass. A filter at the
                             surface, not absorption along the path inside (Beer's law):
                             light crossing a body twice keeps (1 - absorption)^2      */
    struct vec3 emission; /* Le, radiance leaving the front side; zero if it does not emit */
    int two_sided;        /* whether the back side emits Le too (e.g. inside a sphere)  */
    struct vec3 rho_s;    /* Phong: specular ks, kd + ks <= 1; Ward: specular rho_s,
                             rho_d + rho_s <= 1                                       */
    double exponent;      /* Phong: n >= 0, the cosine lobe's exponent (shininess)    */
    double alpha_x;       /* Ward: alpha_x > 0, rms slope along the frame's t axis    */
    double alpha_y;       /* Ward: alpha_y > 0, rms slope along the frame's b axis    */
    double roughness;     /* Schlick: r in [0, 1]; 0 mirror, 1/2 glossy, 1 Lambertian.
                             Jensen 1996's "diffuse-specular parameter"               */
    double isotropy;      /* Schlick: p in (0, 1], never left 0; 1 isotropic, towards 0
                             the highlight stretches along the frame's b axis         */
};

static inline int material_emits(const struct material *m)
{
    return m->emission.x > 0 || m->emission.y > 0 || m->emission.z > 0;
}

/* Whether the material scatters only in ideal specular directions (no diffuse part).
 * Schlick's model with roughness 0 is a perfect mirror (Schlick 1994, Sec. 5). */
static inline int material_is_specular(const struct material *m)
{
    return m->kind == MATERIAL_MIRROR || m->kind == MATERIAL_GLASS ||
           (m->kind == MATERIAL_SCHLICK && m->roughness == 0);
}

#endif
