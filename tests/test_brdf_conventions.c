/*
 * tests/test_brdf_conventions.c -- what every material model (scene/brdf.h), the delta
 * ones included, keeps at its edges: finite samples, values and albedos at extreme
 * directions, nothing below the surface, which kinds are all delta, and the split into
 * diffuse and specular parts (Jensen 1996, Eq. 2) that sum to the whole.
 */
#include <math.h>

#include "../src/base/rng.h"
#include "../src/scene/brdf.h"
#include "brdf_cases.h"
#include "tests.h"

/* Every model once, the delta ones included. */
static int all_cases(struct model_case *cases)
{
    int n = glossy_cases(cases);
    struct model_case mirror = {"mirror", material_of(MATERIAL_MIRROR, vec3(0.9, 0.8, 0.7)), 1};
    struct model_case glass = {"glass", material_of(MATERIAL_GLASS, vec3_zero()), 1};
    glass.m.ior = 1.5;
    cases[n++] = mirror;
    cases[n++] = glass;
    cases[n++] = schlick_case("schlick r=0", vec3(0.5, 0.5, 0.5), 0.0, 1.0);
    return n;
}

/* Samples, evaluations and the albedo of m at wo are all finite (see below). */
static void check_finite_at(struct check *t, const struct material *m,
                            const struct shading_frame *f, struct vec3 wo, uint64_t key)
{
    struct rng rng = rng_stream(SEED, STREAM_TEST, key, 0);
    for (int i = 0; i < 1000; i++) {
        struct brdf_sample s;
        double u0 = rng_uniform(&rng), u1 = rng_uniform(&rng);
        if (!sample_with(m, f, wo, u0, u1, rng_uniform(&rng), &s))
            continue;
        CHECK(t, vec3_is_finite(s.weight) && isfinite(s.pdf) && s.pdf > 0);
        CHECK(t, fabs(vec3_length(s.wi) - 1) < 1e-12);
    }
    struct vec3 wis[3];
    wis[0] = f->n;
    wis[1] = vec3_sub(vec3_scale(f->n, 2 * vec3_dot(wo, f->n)), wo); /* the exact mirror */
    wis[2] = frame_direction(f, 1e-12, 2.0);
    for (int k = 0; k < 3; k++) {
        struct vec3 fr = brdf_eval(m, f, wo, wis[k]);
        double pdf = brdf_pdf(m, f, wo, wis[k]);
        CHECK(t, vec3_is_finite(fr) && vec3_max_component(vec3_neg(fr)) <= 0);
        CHECK(t, isfinite(pdf) && pdf >= 0);
    }
    struct vec3 albedo = brdf_albedo(m, f, wo);
    CHECK(t, vec3_is_finite(albedo) && vec3_max_component(albedo) <= 1);
}

/* truth: no NaN or Inf ever: at wo exactly along n, at cos_o = 1e-12, 1e-90 and 1e-300,
 *   on both sides of glass, every model's samples (1000 each) have finite weights, pdf > 0
 *   and unit wi; eval, pdf and albedo are finite and non-negative for wi along n,
 *   grazing, and wo's exact mirror (where Ward's lobe peaks as 1 / cos^2).
 * catches: 0 / 0 in a half vector at grazing, |wo + wi|^2 underflowing, exp() of huge
 *   arguments times huge normalisations, a lobe frame built from a zero vector. */
static void test_brdf_extreme_directions_stay_finite(struct check *t)
{
    static const double cos_o[] = {1.0, 1e-12, 1e-90, 1e-300};
    struct model_case cases[MAX_CASES];
    int n_cases = all_cases(cases);
    for (int c = 0; c < n_cases; c++) {
        for (int k = 0; k < 8; k++) {
            struct shading_frame f = shading_frame_from_normal(vec3(0, 0, 1), k % 2,
                                                               TRANSPORT_RADIANCE);
            struct vec3 wo = frame_direction(&f, cos_o[k / 2], 0.9);
            check_finite_at(t, &cases[c].m, &f, wo, 4000 + (uint64_t)(c * 8 + k));
        }
    }
}

/* truth: the conventions of brdf.h: reflection models give f = 0 and pdf = 0 for wi
 *   below the surface and refuse to sample when wo is below it; only mirror, glass and
 *   Schlick with r = 0 are all delta (pdf 0 everywhere), and they alone hold no photons.
 * catches: |cos| used where the sign matters (surfaces would transmit), a renderer
 *   storing photons on mirrors. */
static void test_brdf_below_surface_and_kinds(struct check *t)
{
    struct model_case cases[MAX_CASES];
    int n_cases = all_cases(cases);
    struct shading_frame f = test_frame(TRANSPORT_RADIANCE);
    struct vec3 wo = frame_direction(&f, 0.6, 0.2), below = frame_direction(&f, -0.3, 1.0);
    for (int c = 0; c < n_cases; c++) {
        const struct material *m = &cases[c].m;
        struct brdf_sample s;
        CHECK(t, vec3_max_abs(brdf_eval(m, &f, wo, below)) == 0);
        CHECK(t, brdf_pdf(m, &f, wo, below) == 0);
        CHECK(t, !sample_with(m, &f, below, 0.5, 0.5, 0.5, &s));
        int delta = m->kind == MATERIAL_MIRROR || m->kind == MATERIAL_GLASS ||
                    (m->kind == MATERIAL_SCHLICK && m->roughness == 0);
        CHECK(t, brdf_is_delta(m) == delta && brdf_has_non_delta(m) == !delta);
        CHECK(t, !delta || brdf_pdf(m, &f, wo, frame_direction(&f, 0.6, 0.2 + PI)) == 0);
    }
}

/* truth: f_r,d + f_r,s = f_r (Jensen 1996, Eq. 2) for every model, direction by
 * direction; the delta lobes all go to the specular part; a Lambertian diffuse part is
 * the constant rho / pi. */
static void test_brdf_split_sums_to_whole(struct check *t)
{
    struct model_case cases[MAX_CASES + 3];
    int n_cases = all_cases(cases);
    struct shading_frame f = test_frame(TRANSPORT_RADIANCE);
    struct rng rng = rng_stream(SEED, STREAM_TEST, 1001, 0);
    for (int c = 0; c < n_cases; c++) {
        const struct material *m = &cases[c].m;
        struct brdf_split split = brdf_split(m);
        int diffuse = m->kind == MATERIAL_SCHLICK ? m->roughness >= 0.5
                      : m->kind == MATERIAL_MIRROR || m->kind == MATERIAL_GLASS
                          ? 0
                          : vec3_max_component(m->rho) > 0;
        CHECK(t, split.has_diffuse == diffuse);
        CHECK(t, brdf_has_delta(m) ? split.has_specular && brdf_has_delta(&split.specular)
                                   : !split.has_diffuse || !brdf_has_delta(&split.diffuse));
        for (int i = 0; i < 500; i++) {
            double c1 = 1.0 - rng_uniform(&rng), c2 = 1.0 - rng_uniform(&rng);
            struct vec3 wo = frame_direction(&f, c1, 2 * PI * rng_uniform(&rng));
            struct vec3 wi = frame_direction(&f, c2, 2 * PI * rng_uniform(&rng));
            struct vec3 whole = brdf_eval(m, &f, wo, wi);
            struct vec3 d = split.has_diffuse ? brdf_eval(&split.diffuse, &f, wo, wi) : vec3_zero();
            struct vec3 sp = split.has_specular ? brdf_eval(&split.specular, &f, wo, wi)
                                                : vec3_zero();
            CHECK(t, close_vec3(vec3_add(d, sp), whole, 1e-12));
            if (split.has_diffuse && split.lambertian)
                CHECK(t, close_vec3(d, vec3_scale(split.diffuse.rho, 1.0 / PI), 1e-15));
        }
    }
    struct material phong = phong_case("phong", vec3(0.5, 0.3, 0.2), vec3(0.4, 0.4, 0.4), 10).m;
    struct brdf_split split = brdf_split(&phong);
    CHECK(t, split.has_diffuse && split.has_specular && split.lambertian);
    struct brdf_split sand = brdf_split(&cases[9].m); /* schlick r = 0.6: all diffuse */
    CHECK(t, sand.has_diffuse && !sand.has_specular && !sand.lambertian);
}

void test_brdf_conventions(struct check *t)
{
    RUN_TEST(t, test_brdf_extreme_directions_stay_finite);
    RUN_TEST(t, test_brdf_below_surface_and_kinds);
    RUN_TEST(t, test_brdf_split_sums_to_whole);
}
