/*
 * photon/light_patches.h -- a light cut into patches of equal area, each the position a
 * projection map is seen from (Jensen and Christensen 1994, Sec. 3.1), with the bounds
 * marking needs and the sampling of an origin on a patch. Used by projection_map.c only.
 */
#ifndef PHOTON_LIGHT_PATCHES_H
#define PHOTON_LIGHT_PATCHES_H

#include <stddef.h>

#include "../scene/emit.h"
#include "../scene/scene.h"

enum patch_shape {
    PATCH_POINT, PATCH_PARALLELOGRAM, PATCH_TRIANGLE, PATCH_SPHERE_ZONE, PATCH_WHOLE
};

/* One emission position and its map (the map is projection_map.c's). */
struct patch {
    int light;              /* index into scene->lights                                  */
    enum patch_shape shape;
    struct vec3 corner;     /* parallelogram: corner + s a + t b, s, t in [0, 1];
                               triangle: corner, corner + a, corner + b                  */
    struct vec3 a, b;       /* (see corner); both unused for points and sphere zones     */
    double z0, z1;          /* sphere zone: z in [z0, z1] on the unit sphere, world axes  */
    double phi0, dphi;      /* sphere zone: phi in [phi0, phi0 + dphi]                    */
    struct vec3 centre;     /* o: where the map is seen from                              */
    struct vec3 t, bt, n;   /* the map's frame: theta from n, phi from t towards bt       */
    double rho;             /* every origin lies within rho of o (ray offset included)   */
    double beta;            /* every origin's normal lies within beta of n (radians)     */
    double area_fraction;   /* a_k: the patch's area over the light's (1 for a point)    */
    size_t first, n_marked; /* its marked cells in cells[] (invariant (a))               */
};

/* Every emitting light's patches, lights in order: *n_patches of them (the caller owns
 * the array, and fills first and n_marked); *power, the sum of lum(Phi_l) over those
 * lights. */
struct patch *light_patches(const struct scene *scene, size_t *n_patches, double *power);

/* e->origin, a point of patch p of light l uniform by area from u, and e->normal there
 * (the zero vector for a point light or a patch that is the whole sphere). */
void patch_origin(const struct patch *p, const struct light *l, const double u[2],
                  struct emission *e);

/* The largest angle from the middle direction of the cell [theta0, theta1] x [0, dphi]
 * (polar angles from an axis, dphi <= pi) to any direction of it. */
double cell_radius(double theta0, double theta1, double dphi);

/* v turned by the least rotation taking unit `from` to unit `to`, which moves no vector
 * by more than the angle between them (point (2) of projection_map.c). from . to > -1. */
struct vec3 turn_between(struct vec3 v, struct vec3 from, struct vec3 to);

#endif
