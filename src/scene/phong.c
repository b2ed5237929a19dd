/*
 * scene/phong.c -- the energy-conserving modified Phong model (Lafortune & Willems 1994,
 * "Using the modified Phong reflectance model for physically based rendering").
 *
 *   f = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha)
 *
 * alpha is the angle between wi and the mirror direction of wo, and the lobe is zero
 * for alpha > pi / 2. Written as cos(alpha) = 2 cos_o cos_i - wo . wi, which is
 * symmetric in wo and wi, so f is reciprocal to the last bit. With kd + ks <= 1 the
 * albedo is at most 1: exactly kd + ks at normal incidence, and less towards grazing
 * angles, where part of the lobe lies below the surface and the cos_i factor shrinks it.
 *
 * Sampling, as L&W propose: the diffuse lobe with probability P_d = mean(kd) / (mean(kd) +
 * mean(ks)), cosine-weighted; the specular lobe otherwise, with pdf (n + 1) / (2 pi)
 * cos^n(alpha) about the mirror direction: cos(alpha) = u^(1 / (n + 1)). The pdf of a
 * direction is the mixture of the two. Specular samples below the surface are lost (the
 * caller ends the path), which is the model's energy loss at grazing angles.
 * Local coordinates throughout (brdf_models.h): z is the normal.
 */
#include <assert.h>

#include "brdf_models.h"

/* Gauss-Legendre nodes and weights on [0, 1], 16 points (exact for polynomials of
 * degree 31); the weights sum to 1. */
static const double gauss_legendre_16[16][2] = {
    {0.0052995325041750307, 0.013576229705877029}, {0.0277124884633837, 0.031126761969323888},
    {0.067184398806084122, 0.047579255841246448}, {0.1222977958224985, 0.062314485627766973},
    {0.19106187779867811, 0.07479799440828841},   {0.27099161117138632, 0.084578259697501282},
    {0.35919822461037054, 0.091301707522461806},  {0.45249374508118129, 0.094725305227534237},
    {0.54750625491881877, 0.094725305227534237},  {0.64080177538962946, 0.091301707522461806},
    {0.72900838882861363, 0.084578259697501282},  {0.80893812220132189, 0.07479799440828841},
    {0.87770220417750155, 0.062314485627766973},  {0.93281560119391593, 0.047579255841246448},
    {0.9722875115366163, 0.031126761969323888},   {0.99470046749582497, 0.013576229705877029}};

static void assert_phong(const struct material *m)
{
    assert(m->exponent >= 0);
    assert(is_reflectance(m->rho) && is_reflectance(m->rho_s));
    assert(is_reflectance(vec3_add(m->rho, m->rho_s))); /* kd + ks <= 1 */
    (void)m; /* only asserts read it */
}

/* cos^n(alpha) for the lobe, zero beyond pi / 2 (pow(0, 0) would give 1). */
static double phong_lobe(double cos_alpha, double n)
{
    return cos_alpha > 0 ? pow(fmin(cos_alpha, 1.0), n) : 0.0;
}

static double cos_alpha(struct vec3 wo, struct vec3 wi)
{
    return 2.0 * wo.z * wi.z - vec3_dot(wo, wi);
}

struct vec3 phong_eval(const struct material *m, struct vec3 wo, struct vec3 wi)
{
    double n = m->exponent;
    double specular = (n + 2.0) / (2.0 * PI) * phong_lobe(cos_alpha(wo, wi), n);
    return vec3_add(vec3_scale(m->rho, 1.0 / PI), vec3_scale(m->rho_s, specular));
}

double phong_pdf(const struct material *m, struct vec3 wo, struct vec3 wi)
{
    double p_s = specular_probability(m);
    if (p_s < 0)
        return 0.0;
    double n = m->exponent;
    double specular = (n + 1.0) / (2.0 * PI) * phong_lobe(cos_alpha(wo, wi), n);
    return (1.0 - p_s) * wi.z / PI + p_s * specular;
}

int phong_sample(const struct material *m, struct vec3 wo, const double u[3],
                 struct brdf_sample *s)
{
    assert_phong(m);
    double p_s = specular_probability(m);
    if (p_s < 0)
        return 0;
    if (u[0] >= p_s) {
        s->wi = sample_cosine_local(u[1], u[2]);
        return 1;
    }
    struct vec3 mirror = vec3(-wo.x, -wo.y, wo.z), a, b;
    vec3_frame(mirror, &a, &b);
    double cos_a = pow(u[1], 1.0 / (m->exponent + 1.0));
    double sin_a = sqrt(fmax(0.0, 1.0 - cos_a * cos_a)), phi = 2.0 * PI * u[2];
    s->wi = vec3_add(vec3_add(vec3_scale(a, sin_a * cos(phi)), vec3_scale(b, sin_a * sin(phi))),
                     vec3_scale(mirror, cos_a));
    return 1;
}

/* g(x) = integral over the azimuth beta about the mirror direction of max(0, cos_i),
 * where cos_i = x cos_o + sqrt(1 - x^2) sin_o cos(beta) for a direction at cos(alpha) = x.
 * Writing cos_i = A + B cos(beta): 2 pi A when A >= B (the whole circle is above the
 * surface), else 2 (A beta_0 + B sin(beta_0)) with cos(beta_0) = -A / B. */
static double azimuth_integral(double x, double cos_o, double sin_o)
{
    double a = x * cos_o, b = sqrt(fmax(0.0, 1.0 - x * x)) * sin_o;
    if (b <= a)
        return 2.0 * PI * a;
    double ratio = a / b; /* in [0, 1): b > a >= 0 */
    return 2.0 * (a * acos(-ratio) + b * sqrt(1.0 - ratio * ratio));
}

/* The specular lobe's albedo, (n + 2) / (2 pi) times the integral of cos^n(alpha)
 * max(0, cos_i) over the lobe's hemisphere; x = cos(alpha) in [0, 1].
 * Where x >= sin_o the lobe's whole circle lies above the surface: that part is
 * cos_o (1 - sin_o^(n + 2)) in closed form. The rest, x in [0, sin_o], is
 *   (n + 2) / (2 pi (n + 1)) sin_o^(n + 1) * integral_0^1 g(sin_o y^(1 / (n + 1))) dy
 * after y = (x / sin_o)^(n + 1), which absorbs x^n. g has a (sin_o - x)^(3/2) kink at
 * the upper end and y^(1 / (n + 1)) a root at the lower one; y = (1 - cos(pi t)) / 2
 * flattens both, and 16 Gauss-Legendre points in t then err by less than 1e-6 for all
 * n >= 0 and angles up to grazing (checked against 131072-point composite rules). */
static double specular_albedo(struct vec3 wo, double n)
{
    double cos_o = wo.z, sin_o = sqrt(wo.x * wo.x + wo.y * wo.y);
    double outer = pow(sin_o, n + 1.0);
    double albedo = cos_o * (1.0 - outer * sin_o);
    if (outer < 1e-12)
        return albedo; /* the rest is at most 2 sin_o^(n + 1) */
    double sum = 0.0;
    for (int k = 0; k < 16; k++) {
        double t = gauss_legendre_16[k][0];
        double y = 0.5 * (1.0 - cos(PI * t)), dy_dt = 0.5 * PI * sin(PI * t);
        double x = sin_o * pow(y, 1.0 / (n + 1.0));
        sum += gauss_legendre_16[k][1] * dy_dt * azimuth_integral(x, cos_o, sin_o);
    }
    return albedo + (n + 2.0) / (2.0 * PI * (n + 1.0)) * outer * sum;
}

struct vec3 phong_albedo(const struct material *m, struct vec3 wo)
{
    assert_phong(m);
    return vec3_add(m->rho, vec3_scale(m->rho_s, specular_albedo(wo, m->exponent)));
}
