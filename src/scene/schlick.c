/*
 * scene/schlick.c -- Schlick's single-slope model (Schlick 1994, "An inexpensive BRDF
 * model for physically-based rendering"), the model Jensen 1996 (Sec. 6) renders the
 * sphere flake with ("diffuse-specular parameter 0.1") and the sand under the cognac
 * glass (0.6). We read that parameter as Schlick's roughness r: 0 a perfect mirror,
 * 1 a Lambertian surface.
 *
 * Schlick's material (C, r, p): colour C, roughness r in [0, 1], isotropy p in (0, 1].
 * Sec. 5 splits the reflection between a Lambertian, a glossy and a specular part,
 *   b = 4 r (1 - r);  a = 1 - b, c = 0 when r >= 1/2;  a = 0, c = 1 - b when r < 1/2,
 *   f = C [a / pi + b D(h) G1(wo) G1(wi) / (4 cos_o cos_i)] + C c delta(wi = mirror of wo),
 * so r = 1/2 is purely glossy. The glossy part is a microfacet lobe on Schlick's zenith
 * factor Z(t) = r / (1 + r t^2 - t^2)^2, t = h . n (Sec. 5), which is the Trowbridge-
 * Reitz ("GGX") distribution with alpha^2 = r: D(h) = Z(t) / pi when p = 1.
 *
 * Departs from Sec. 5 in three places, each to keep the model energy conserving and its
 * sampling exact:
 *  - The spectral factor is C, not Schlick's Fresnel approximation C + (1 - C)(1 - u)^5,
 *    so that C is the reflectance as in the other models and the albedo is at most C.
 *  - Masking-shadowing is Smith's exact G1 for this distribution (Walter et al. 2007,
 *    Eq. 34), not Schlick's approximation G(v) = v / (r - r v + v), with which the albedo
 *    exceeds 1 at grazing angles for small r (2.6 at cos_o = 0.01 for r = 0.01, by
 *    quadrature).
 *  - Anisotropy stretches the distribution, ax = sqrt(r p) along t and ay = sqrt(r / p)
 *    along b, instead of multiplying Z(t) by A(w) = sqrt(p / (p^2 - p^2 w^2 + w^2)).
 *    Schlick's A is normalised only approximately (its mean over the azimuth is
 *    sqrt(p) / AGM(1, p), 0.74 at p = 0.1) and admits no closed-form masking; the
 *    stretched lobe's azimuth density is p / (p^2 - p^2 w^2 + w^2), the square of
 *    Schlick's A and normalised exactly, and p = 1 gives back Z(t).
 * Energy removed by masking is not returned (no multiple scattering): a white surface
 * with r = 1/2 reflects 0.50 at normal incidence and 0.73 at grazing.
 *
 * Sampling picks the specular part with probability c, the Lambertian with a, the glossy
 * with b; a glossy half vector has density D(h) (h . n) (Walter et al. 2007, Eqs. 35-36,
 * with the azimuth of brdf_models.h), and wi = reflect(wo, h) has p_h / (4 wo . h).
 * With G1 written as 2 cos / (cos + sqrt(cos^2 + ax^2 x^2 + ay^2 y^2)), the 4 cos_o cos_i
 * cancels and f stays finite at grazing angles. Local coordinates (brdf_models.h).
 */
#include <assert.h>

#include "brdf_models.h"

/* The weights of the Lambertian (a), glossy (b) and specular (c) parts; a + b + c = 1. */
struct schlick_parts {
    double a, b, c;
};

static struct schlick_parts schlick_parts(double r)
{
    struct schlick_parts w;
    w.b = 4.0 * r * (1.0 - r);
    w.a = r >= 0.5 ? 1.0 - w.b : 0.0;
    w.c = r >= 0.5 ? 0.0 : 1.0 - w.b;
    return w;
}

static void assert_schlick(const struct material *m)
{
    assert(m->roughness >= 0 && m->roughness <= 1);
    assert(m->isotropy > 0 && m->isotropy <= 1);
    assert(is_reflectance(m->rho));
    (void)m; /* only asserts read it */
}

/* The stretched slopes ax, ay; called only when the glossy part exists (0 < r < 1). */
static void schlick_alphas(const struct material *m, double *ax, double *ay)
{
    *ax = sqrt(m->roughness * m->isotropy);
    *ay = sqrt(m->roughness / m->isotropy); /* p > 0 */
}

/* D(h) for unit h with h.z > 0: 1 / (pi ax ay (h.z^2 + (h.x / ax)^2 + (h.y / ay)^2)^2),
 * the anisotropic Trowbridge-Reitz form; the bracket is at least min(1, 1 / ay^2) > 0. */
static double distribution(double ax, double ay, struct vec3 h)
{
    double sx = h.x / ax, sy = h.y / ay;
    double q = h.z * h.z + sx * sx + sy * sy;
    return 1.0 / (PI * ax * ay * q * q);
}

/* cos + sqrt(cos^2 + ax^2 x^2 + ay^2 y^2) = 2 cos / G1(w): positive when w.z > 0. */
static double masking_denominator(double ax, double ay, struct vec3 w)
{
    double sx = ax * w.x, sy = ay * w.y;
    return w.z + sqrt(w.z * w.z + sx * sx + sy * sy);
}

struct vec3 schlick_eval(const struct material *m, struct vec3 wo, struct vec3 wi)
{
    struct schlick_parts w = schlick_parts(m->roughness);
    double f = w.a / PI;
    if (w.b > 0) {
        double ax, ay;
        schlick_alphas(m, &ax, &ay);
        struct vec3 h = half_vector_of(wo, wi);
        /* D G1(wo) G1(wi) / (4 cos_o cos_i) = D / (den(wo) den(wi)) */
        f += w.b * distribution(ax, ay, h) /
             (masking_denominator(ax, ay, wo) * masking_denominator(ax, ay, wi));
    }
    return vec3_scale(m->rho, f);
}

double schlick_pdf(const struct material *m, struct vec3 wo, struct vec3 wi)
{
    struct schlick_parts w = schlick_parts(m->roughness);
    double pdf = w.a * wi.z / PI;
    if (w.b > 0) {
        double ax, ay;
        schlick_alphas(m, &ax, &ay);
        struct vec3 h = half_vector_of(wo, wi);
        double wo_h = vec3_dot(wo, h);
        if (wo_h > 0)
            pdf += w.b * distribution(ax, ay, h) * h.z / (4.0 * wo_h);
    }
    return pdf;
}

int schlick_sample(const struct material *m, struct vec3 wo, const double u[3],
                   struct brdf_sample *s)
{
    assert_schlick(m);
    struct schlick_parts w = schlick_parts(m->roughness);
    if (!(channel_mean(m->rho) > 0))
        return 0;
    if (u[0] < w.c) { /* the specular part: weight C c / c */
        s->wi = vec3(-wo.x, -wo.y, wo.z);
        s->weight = m->rho;
        s->pdf = w.c;
        s->delta = 1;
        return 1;
    }
    if (u[0] < w.c + w.a) {
        s->wi = sample_cosine_local(u[1], u[2]);
        return 1;
    }
    double ax, ay, cos_phi, sin_phi;
    schlick_alphas(m, &ax, &ay); /* b > 0 here: u[0] < 1 = a + b + c */
    sample_stretched_azimuth(ax, ay, u[2], &cos_phi, &sin_phi);
    double cx = cos_phi / ax, sy = sin_phi / ay;
    double tan2_theta = u[1] / ((1.0 - u[1]) * (cx * cx + sy * sy)); /* u[1] < 1 */
    struct vec3 h = half_vector_local(tan2_theta, cos_phi, sin_phi);
    s->wi = vec3_sub(vec3_scale(h, 2.0 * vec3_dot(wo, h)), wo); /* below if wo . h < 0 */
    return 1;
}
