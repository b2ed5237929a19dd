/*
 * scene/optics.c -- reflection, Snell's law and the Fresnel equations (optics.h).
 */
#include "optics.h"

struct vec3 reflect(struct vec3 wo, struct vec3 n)
{
    return vec3_sub(vec3_scale(n, 2.0 * vec3_dot(wo, n)), wo);
}

int refract(struct vec3 wo, struct vec3 n, double eta, struct vec3 *wi)
{
    double cos_i = vec3_dot(wo, n);
    /* Snell: sin_t = sin_i / eta. */
    double sin2_t = fmax(0.0, 1.0 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0)
        return 0;
    double cos_t = sqrt(1.0 - sin2_t);
    *wi = vec3_normalize(vec3_add(vec3_scale(wo, -1.0 / eta),
                                  vec3_scale(n, cos_i / eta - cos_t)));
    return 1;
}

double fresnel_dielectric(double cos_i, double eta)
{
    double sin2_t = fmax(0.0, 1.0 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0)
        return 1.0; /* total internal reflection */
    double cos_t = sqrt(1.0 - sin2_t);
    /* r_parallel = (eta cos_i - cos_t) / (eta cos_i + cos_t),
     * r_perpendicular = (cos_i - eta cos_t) / (cos_i + eta cos_t); both denominators are
     * positive since eta > 0, cos_i > 0 and cos_t >= 0. */
    double r_par = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    double r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5 * (r_par * r_par + r_perp * r_perp);
}
