/*
 * tests/brdf_cases.c -- the cases, frames, directions and samples behind brdf_cases.h.
 */
#include "brdf_cases.h"

#include <math.h>
#include <string.h>

#include "../src/base/rng.h"

struct material material_of(enum material_kind kind, struct vec3 rho)
{
    struct material m;
    memset(&m, 0, sizeof m);
    m.kind = kind;
    m.rho = rho;
    m.isotropy = 1.0;
    return m;
}

struct model_case phong_case(const char *name, struct vec3 kd, struct vec3 ks,
                             double n)
{
    struct model_case c = {name, material_of(MATERIAL_PHONG, kd), 1};
    c.m.rho_s = ks;
    c.m.exponent = n;
    return c;
}

static struct model_case ward_case(const char *name, struct vec3 rho_d, struct vec3 rho_s,
                                   double ax, double ay)
{
    struct model_case c = {name, material_of(MATERIAL_WARD, rho_d), 0};
    c.m.rho_s = rho_s;
    c.m.alpha_x = ax;
    c.m.alpha_y = ay;
    return c;
}

struct model_case schlick_case(const char *name, struct vec3 colour, double r, double p)
{
    struct model_case c = {name, material_of(MATERIAL_SCHLICK, colour), r == 1};
    c.m.roughness = r;
    c.m.isotropy = p;
    return c;
}

int glossy_cases(struct model_case *cases)
{
    int n = 0;
    struct model_case lambert = {"lambert", material_of(MATERIAL_LAMBERT, vec3(0.8, 0.5, 0.2)),
                                 1};
    cases[n++] = lambert;
    cases[n++] = phong_case("phong n=10", vec3(0.5, 0.3, 0.2), vec3(0.4, 0.4, 0.4), 10);
    cases[n++] = phong_case("phong n=1000", vec3(0, 0, 0), vec3(1, 1, 1), 1000);
    cases[n++] = phong_case("phong n=1", vec3(0.2, 0.2, 0.2), vec3(0.7, 0.0, 0.7), 1);
    cases[n++] = phong_case("phong n=0", vec3(0.1, 0.1, 0.1), vec3(0.9, 0.9, 0.9), 0);
    cases[n++] = ward_case("ward 0.05/0.3", vec3(0.2, 0.2, 0.2), vec3(0.7, 0.7, 0.7), 0.05, 0.3);
    cases[n++] = ward_case("ward 0.2", vec3(0, 0, 0), vec3(1, 1, 1), 0.2, 0.2);
    cases[n++] = ward_case("ward 0.5", vec3(0.5, 0.2, 0.0), vec3(0.4, 0.4, 0.4), 0.5, 0.5);
    cases[n++] = schlick_case("schlick r=0.1", vec3(0.8, 0.8, 0.6), 0.1, 1.0);
    cases[n++] = schlick_case("schlick r=0.6", vec3(0.7, 0.6, 0.4), 0.6, 1.0);
    cases[n++] = schlick_case("schlick r=0.5 p=0.2", vec3(1, 1, 1), 0.5, 0.2);
    cases[n++] = schlick_case("schlick r=0.02", vec3(0.9, 0.9, 0.9), 0.02, 1.0);
    cases[n++] = schlick_case("schlick r=1", vec3(0.6, 0.6, 0.6), 1.0, 1.0);
    return n;
}

struct shading_frame test_frame(enum transport transport)
{
    return shading_frame_from_normal(vec3_normalize(vec3(0.3, -0.5, 0.8)), 1, transport);
}

struct vec3 frame_direction(const struct shading_frame *f, double cos_theta, double phi)
{
    double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    return vec3_add(vec3_add(vec3_scale(f->t, sin_theta * cos(phi)),
                             vec3_scale(f->b, sin_theta * sin(phi))),
                    vec3_scale(f->n, cos_theta));
}

int close_vec3(struct vec3 a, struct vec3 b, double rel)
{
    double scale = fmax(vec3_max_abs(a), vec3_max_abs(b));
    return vec3_max_abs(vec3_sub(a, b)) <= rel * scale;
}

int sample_with(const struct material *m, const struct shading_frame *f, struct vec3 wo,
                double u0, double u1, double u2, struct brdf_sample *s)
{
    double u[3];
    u[0] = u0;
    u[1] = u1;
    u[2] = u2;
    return brdf_sample(m, f, wo, u, s);
}

void estimate_albedo(const struct material *m, const struct shading_frame *f,
                     struct vec3 wo, uint64_t key, long n, struct vec3 *mean,
                     struct vec3 *five_se)
{
    struct rng rng = rng_stream(SEED, STREAM_TEST, key, 0);
    struct vec3 sum = vec3_zero(), sum2 = vec3_zero();
    for (long i = 0; i < n; i++) {
        struct brdf_sample s;
        double u0 = rng_uniform(&rng), u1 = rng_uniform(&rng);
        if (!sample_with(m, f, wo, u0, u1, rng_uniform(&rng), &s))
            continue;
        sum = vec3_add(sum, s.weight);
        sum2 = vec3_add(sum2, vec3_mul(s.weight, s.weight));
    }
    *mean = vec3_scale(sum, 1.0 / n);
    struct vec3 var = vec3_max(vec3_sub(vec3_scale(sum2, 1.0 / n), vec3_mul(*mean, *mean)),
                               vec3_zero());
    *five_se = vec3(5 * sqrt(var.x / n), 5 * sqrt(var.y / n), 5 * sqrt(var.z / n));
}

int at_most(struct vec3 a, struct vec3 b, struct vec3 tolerance)
{
    return vec3_max_component(vec3_sub(a, vec3_add(b, tolerance))) <= 0;
}
