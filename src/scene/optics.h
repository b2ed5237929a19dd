/*
 * scene/optics.h -- ideal specular reflection and refraction at a smooth surface.
 *
 * Directions follow the pbrt convention the rest of photon uses: wo and wi both point
 * AWAY from the surface, and n is a unit normal on the side of wo.
 */
#ifndef PHOTON_OPTICS_H
#define PHOTON_OPTICS_H

#include "../base/vec3.h"

/* Mirror direction of wo about n: wi = 2 (wo . n) n - wo. */
struct vec3 reflect(struct vec3 wo, struct vec3 n);

/* Refracted direction wi of wo through a surface with relative index eta = n_t / n_i
 * (the side of wi over the side of wo), by Snell's law. Returns 0 on total internal
 * reflection (no refracted direction), else 1 with *wi unit length. */
int refract(struct vec3 wo, struct vec3 n, double eta, struct vec3 *wi);

/* Unpolarised Fresnel reflectance of a smooth dielectric boundary, exact (not Schlick),
 * for cos_i = cos of the angle of incidence on the wo side (> 0) and eta = n_t / n_i.
 * 1 on total internal reflection. */
double fresnel_dielectric(double cos_i, double eta);

#endif
