/*
 * scene/brdf_models.h -- the glossy models behind brdf.c, in local shading coordinates.
 *
 * Internal to scene/: brdf.c turns world directions into local ones (x along the frame's
 * t, y along b, z along n) and calls these. The caller guarantees wo.z > 0 everywhere and
 * wi.z > 0 for *_eval and *_pdf; vectors are unit length.
 *
 * X_sample() picks a lobe with u[0] and a direction with u[1], u[2] and sets s->wi. For
 * a delta lobe it also sets s->delta = 1, s->weight and s->pdf; for a non-delta lobe it
 * leaves them to brdf.c, which computes weight = X_eval cos / X_pdf so that the weight,
 * the pdf and the evaluation can never disagree. It returns 0 when the material is black
 * (no lobe to pick); a wi below the surface is brdf.c's to refuse.
 */
#ifndef PHOTON_BRDF_MODELS_H
#define PHOTON_BRDF_MODELS_H

#include "brdf_sample.h"
#include "material.h"

struct vec3 phong_eval(const struct material *m, struct vec3 wo, struct vec3 wi);
double phong_pdf(const struct material *m, struct vec3 wo, struct vec3 wi);
int phong_sample(const struct material *m, struct vec3 wo, const double u[3],
                 struct brdf_sample *s);
struct vec3 phong_albedo(const struct material *m, struct vec3 wo);

struct vec3 ward_eval(const struct material *m, struct vec3 wo, struct vec3 wi);
double ward_pdf(const struct material *m, struct vec3 wo, struct vec3 wi);
int ward_sample(const struct material *m, struct vec3 wo, const double u[3],
                struct brdf_sample *s);

struct vec3 schlick_eval(const struct material *m, struct vec3 wo, struct vec3 wi);
double schlick_pdf(const struct material *m, struct vec3 wo, struct vec3 wi);
int schlick_sample(const struct material *m, struct vec3 wo, const double u[3],
                   struct brdf_sample *s);

/* Whether a reflectance lies in [0, 1] per channel: the energy bound brdf.h promises. */
static inline int is_reflectance(struct vec3 c)
{
    return c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x <= 1 && c.y <= 1 && c.z <= 1;
}

/* Mean of the three channels: the reflectance that picks a lobe. Using the mean rather
 * than luminance keeps a lobe that reflects only blue from never being sampled. */
static inline double channel_mean(struct vec3 c)
{
    return (c.x + c.y + c.z) / 3.0;
}

/* Probability of sampling the specular lobe of a two-lobe model (phong, ward), by the
 * lobes' mean reflectances rho (diffuse) and rho_s; -1 when the material is black. */
static inline double specular_probability(const struct material *m)
{
    double diffuse = channel_mean(m->rho), specular = channel_mean(m->rho_s);
    if (!(diffuse + specular > 0))
        return -1.0;
    return specular / (diffuse + specular);
}

/* Cosine-weighted direction about +z (Malley's method: a uniform point on the unit disc
 * lifted to the hemisphere); pdf cos / pi. z = sqrt(1 - u1) > 0 since u1 < 1. */
static inline struct vec3 sample_cosine_local(double u1, double u2)
{
    double radius = sqrt(u1), phi = 2.0 * PI * u2;
    return vec3(radius * cos(phi), radius * sin(phi), sqrt(1.0 - u1));
}

/* The azimuth of a half vector for a distribution stretched by ax along x and ay along
 * y: tan(phi) = (ay / ax) tan(2 pi u) (Walter 2005, "Notes on the Ward BRDF"), as
 * (cos phi, sin phi) without atan. The hypotenuse is positive since ax, ay > 0. */
static inline void sample_stretched_azimuth(double ax, double ay, double u, double *cos_phi,
                                            double *sin_phi)
{
    double cx = ax * cos(2.0 * PI * u), cy = ay * sin(2.0 * PI * u);
    double len = sqrt(cx * cx + cy * cy);
    *cos_phi = cx / len;
    *sin_phi = cy / len;
}

/* The unit half vector of wo and wi, both above the surface (so h.z > 0). wo + wi is
 * divided by its largest component before normalising: when both lie within 1e-154 of
 * the surface's plane, mirrored, |wo + wi|^2 would underflow to zero. */
static inline struct vec3 half_vector_of(struct vec3 wo, struct vec3 wi)
{
    struct vec3 h = vec3_add(wo, wi);
    return vec3_normalize(vec3_scale(h, 1.0 / vec3_max_abs(h)));
}

/* The unit half vector at polar angle theta (given tan^2 theta >= 0, possibly infinite)
 * and azimuth phi. */
static inline struct vec3 half_vector_local(double tan2_theta, double cos_phi, double sin_phi)
{
    double cos_theta = 1.0 / sqrt(1.0 + tan2_theta);
    double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    return vec3(sin_theta * cos_phi, sin_theta * sin_phi, cos_theta);
}

#endif
