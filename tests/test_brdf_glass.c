/*
 * tests/test_brdf_glass.c -- the delta models (scene/brdf.h): the optics of glass (the
 * Fresnel equations, Snell's law, total internal reflection, the radiance scaling
 * 1 / eta^2), its colour filter, and the delta lobes of glass and the mirror against
 * brdf_sample(). The glossy models are test_brdf.c's.
 *
 * Truths: the closed forms of a smooth dielectric of index 1.5 (Hecht), and the mean
 * weight of many samples per lobe (fixed seeds, 5 standard errors).
 */
#include <math.h>

#include "../src/base/rng.h"
#include "../src/scene/brdf.h"
#include "brdf_cases.h"
#include "tests.h"

/* truth: a colour filter T on refraction, by hand: every refracted sample's weight is
 *   T (times 1 / eta^2 for radiance), every reflected one's white; the albedo is
 *   F + (1 - F) T, at normal incidence 0.04 + 0.96 T (F = 0.04 for index 1.5, Hecht),
 *   and brdf_albedo() matches the mean weight of 20,000 samples within 5 SE at 0, 60 and
 *   85 degrees, from both sides (beyond the critical angle inside, F = 1: white).
 * tolerance: 1e-12 for closed forms; 5 standard errors for the sampled means.
 * catches: the filter applied to reflection too, or not at all, or as its complement
 *   (the absorption), the albedo left at 1 for coloured glass, Fresnel taken from the
 *   wrong side. */
static void test_coloured_glass(struct check *t)
{
    struct material glass = material_of(MATERIAL_GLASS, vec3_zero());
    glass.ior = 1.5;
    glass.absorption = vec3(0.2, 0.5, 0.9); /* T = (0.8, 0.5, 0.1) */
    struct vec3 filter = vec3(0.8, 0.5, 0.1);
    static const double theta_deg[] = {0, 60, 85};
    for (int front = 0; front <= 1; front++) {
        struct shading_frame f = test_frame(TRANSPORT_IMPORTANCE);
        f = shading_frame_from_normal(f.n, front, TRANSPORT_IMPORTANCE);
        for (int w = 0; w < 3; w++) {
            struct vec3 wo = frame_direction(&f, cos(theta_deg[w] * PI / 180), 0.4);
            struct brdf_sample r, s;
            CHECK(t, sample_with(&glass, &f, wo, 0.0, 0.5, 0.5, &r) && !r.transmitted);
            CHECK(t, vec3_max_abs(vec3_sub(r.weight, vec3(1, 1, 1))) == 0);
            if (sample_with(&glass, &f, wo, 0.999999, 0.5, 0.5, &s) && s.transmitted)
                CHECK(t, vec3_max_abs(vec3_sub(s.weight, filter)) <= 1e-12);
            struct vec3 mean, tol, albedo = brdf_albedo(&glass, &f, wo);
            estimate_albedo(&glass, &f, wo, 4000 + (uint64_t)(3 * front + w), 20000, &mean,
                            &tol);
            CHECK(t, at_most(mean, albedo, tol) && at_most(albedo, mean, tol));
        }
    }
    struct shading_frame f = test_frame(TRANSPORT_IMPORTANCE);
    struct vec3 albedo = brdf_albedo(&glass, &f, f.n);
    struct vec3 normal = vec3_add(vec3(0.04, 0.04, 0.04), vec3_scale(filter, 0.96));
    CHECK(t, vec3_max_abs(vec3_sub(albedo, normal)) <= 1e-12);
    struct shading_frame radiance = test_frame(TRANSPORT_RADIANCE);
    struct brdf_sample s;
    CHECK(t, sample_with(&glass, &radiance, radiance.n, 0.999999, 0.5, 0.5, &s));
    CHECK(t, s.transmitted && vec3_max_abs(vec3_sub(s.weight, vec3_scale(filter, 1 / 2.25)))
                                  <= 1e-12);
}

/* One refraction from wo through glass (1.5) against Snell's law and 1 / eta^2. */
static void check_refraction(struct check *t, const struct shading_frame *f, double theta_deg,
                             double phi)
{
    struct material glass = material_of(MATERIAL_GLASS, vec3_zero());
    glass.ior = 1.5;
    double n_i = f->front ? 1.0 : 1.5, n_t = f->front ? 1.5 : 1.0;
    struct vec3 wo = frame_direction(f, cos(theta_deg * PI / 180), phi);
    struct brdf_sample s;
    CHECK(t, sample_with(&glass, f, wo, 0.999999, 0.5, 0.5, &s) && s.transmitted);
    double sin_i = vec3_length(vec3_cross(wo, f->n));
    double sin_t = vec3_length(vec3_cross(s.wi, f->n));
    CHECK_CLOSE(t, n_i * sin_i, n_t * sin_t, 1e-12);
    CHECK(t, vec3_dot(s.wi, f->n) < 0 && fabs(vec3_dot(s.wi, vec3_cross(wo, f->n))) < 1e-12);
    CHECK_CLOSE(t, vec3_length(s.wi), 1.0, 1e-15);
    CHECK_CLOSE(t, s.weight.x, (n_i / n_t) * (n_i / n_t), 1e-15);
}

/* truth: optics of a smooth dielectric, ior 1.5 (Hecht): F = ((1.5 - 1) / (1.5 + 1))^2 =
 *   0.04 at normal incidence from either side; from inside beyond the critical angle
 *   asin(1 / 1.5) = 41.8 degrees, reflection with probability 1 whatever u; a refracted
 *   direction obeys Snell's law n_i sin_i = n_t sin_t (1e-12), lies in the plane of wo
 *   and n, on the other side; its radiance weight is 1 / eta^2 = (n_i / n_t)^2. The lobe
 *   is reflection for u[0] < F, refraction above (F = 0.0892 at 60 degrees).
 * catches: eta inverted for the back side, Fresnel by Schlick's approximation (0.04 at
 *   normal incidence too, but 0.070 at 60 degrees where the Fresnel equations give
 *   0.0891867128), TIR refracting, the radiance scaling missing, the lobe chosen with
 *   a probability other than the pdf it reports. */
static void test_brdf_glass_optics(struct check *t)
{
    struct material glass = material_of(MATERIAL_GLASS, vec3_zero());
    glass.ior = 1.5;
    struct shading_frame out = test_frame(TRANSPORT_RADIANCE);
    struct shading_frame in = shading_frame_from_normal(out.n, 0, TRANSPORT_RADIANCE);
    struct brdf_sample s;
    CHECK(t, sample_with(&glass, &out, out.n, 0.0, 0.5, 0.5, &s) && !s.transmitted);
    CHECK_CLOSE(t, s.pdf, 0.04, 1e-15);
    CHECK(t, sample_with(&glass, &in, in.n, 0.0, 0.5, 0.5, &s) && !s.transmitted);
    CHECK_CLOSE(t, s.pdf, 0.04, 1e-15);
    CHECK(t, sample_with(&glass, &out, frame_direction(&out, 0.5, 1.0), 0.0, 0.5, 0.5, &s));
    CHECK_CLOSE(t, s.pdf, 0.0891867128, 1e-10); /* Fresnel equations, 60 degrees, 1.5 */
    CHECK(t, sample_with(&glass, &out, frame_direction(&out, 0.5, 1.0), 0.0891, 0.5, 0.5, &s));
    CHECK(t, !s.transmitted); /* u below F reflects, above it refracts */
    CHECK(t, sample_with(&glass, &out, frame_direction(&out, 0.5, 1.0), 0.0893, 0.5, 0.5, &s));
    CHECK(t, s.transmitted && fabs(s.pdf - (1 - 0.0891867128)) < 1e-10);
    for (int k = 0; k < 3; k++) { /* 45 degrees inside: beyond the critical angle */
        struct vec3 wo = frame_direction(&in, cos(45 * PI / 180), 2.0);
        CHECK(t, sample_with(&glass, &in, wo, k / 2.0 * 0.999999, 0.5, 0.5, &s));
        CHECK(t, !s.transmitted && s.pdf == 1 && s.weight.x == 1);
        struct vec3 mirror = vec3_sub(vec3_scale(in.n, 2 * vec3_dot(wo, in.n)), wo);
        CHECK(t, vec3_max_abs(vec3_sub(s.wi, mirror)) < 1e-15);
    }
    static const double theta_deg[] = {10, 30, 60, 89};
    for (int k = 0; k < 4; k++)
        check_refraction(t, &out, theta_deg[k], 0.3 + k);
    check_refraction(t, &in, 41.0, 1.0); /* just inside the critical angle */
    check_refraction(t, &in, 20.0, 5.0);
}

/* Each lobe of brdf_delta_lobes() against the mean weight brdf_sample() gives it. */
static void check_lobes_against_samples(struct check *t, const struct material *m,
                                        const struct shading_frame *f, struct vec3 wo,
                                        uint64_t key)
{
    struct brdf_sample lobes[2];
    int n_lobes = brdf_delta_lobes(m, f, wo, lobes);
    struct rng rng = rng_stream(SEED, STREAM_TEST, key, 0);
    const long n = 200000;
    double sum[2] = {0, 0}, sum2[2] = {0, 0};
    int same_direction = 1;
    for (long i = 0; i < n; i++) {
        struct brdf_sample s;
        double u0 = rng_uniform(&rng);
        if (!sample_with(m, f, wo, u0, 0.5, 0.5, &s))
            continue;
        int lobe = n_lobes == 2 && s.transmitted == lobes[1].transmitted;
        same_direction &= vec3_max_abs(vec3_sub(s.wi, lobes[lobe].wi)) == 0;
        sum[lobe] += s.weight.x;
        sum2[lobe] += s.weight.x * s.weight.x;
    }
    CHECK(t, same_direction);
    for (int k = 0; k < n_lobes; k++) {
        double mean = sum[k] / n, var = fmax(0.0, sum2[k] / n - mean * mean);
        CHECK_CLOSE(t, lobes[k].weight.x, mean, 5 * sqrt(var / n) + 1e-15);
        CHECK(t, lobes[k].pdf == 1 && lobes[k].delta);
    }
}

/* truth: the closed forms of the lobes (Hecht): for glass of index 1.5, reflection F (the
 *   Fresnel equations: 0.04 at normal incidence, 0.0891867128 at 60 degrees) and
 *   refraction (1 - F) / eta^2 for radiance; under total internal reflection one lobe of
 *   weight 1; the mirror one lobe of weight rho. Brute force: the mean weight of
 *   brdf_sample() per lobe over n random u equals that lobe's weight.
 * tolerance: 1e-10 for closed forms (the values are quoted to 10 digits); 5 standard
 *   errors for the sampled means (deterministic seed).
 * catches: the probability not folded in (glass's weights would be 1 and 1/eta^2), a lobe
 *   counted twice (the mirror, TIR), the refraction lobe missing, directions other than
 *   brdf_sample()'s. */
static void test_brdf_delta_lobes(struct check *t)
{
    struct material glass = material_of(MATERIAL_GLASS, vec3_zero());
    glass.ior = 1.5;
    struct shading_frame out = test_frame(TRANSPORT_RADIANCE);
    struct shading_frame in = shading_frame_from_normal(out.n, 0, TRANSPORT_RADIANCE);
    struct brdf_sample lobes[2];
    CHECK(t, brdf_delta_lobes(&glass, &out, out.n, lobes) == 2);
    CHECK_CLOSE(t, lobes[0].weight.x, 0.04, 1e-12);
    CHECK_CLOSE(t, lobes[1].weight.x, 0.96 / 2.25, 1e-12);
    CHECK(t, !lobes[0].transmitted && lobes[1].transmitted);
    struct vec3 at_60 = frame_direction(&out, 0.5, 1.0);
    CHECK(t, brdf_delta_lobes(&glass, &out, at_60, lobes) == 2);
    CHECK_CLOSE(t, lobes[0].weight.x, 0.0891867128, 1e-10);
    CHECK_CLOSE(t, lobes[1].weight.x, (1 - 0.0891867128) / 2.25, 1e-10);
    struct vec3 beyond_critical = frame_direction(&in, cos(45 * PI / 180), 2.0);
    CHECK(t, brdf_delta_lobes(&glass, &in, beyond_critical, lobes) == 1);
    CHECK(t, !lobes[0].transmitted && lobes[0].weight.x == 1);
    struct material mirror = material_of(MATERIAL_MIRROR, vec3(0.9, 0.5, 0.2));
    CHECK(t, brdf_delta_lobes(&mirror, &out, at_60, lobes) == 1);
    CHECK(t, vec3_max_abs(vec3_sub(lobes[0].weight, vec3(0.9, 0.5, 0.2))) == 0);
    CHECK(t, brdf_delta_lobes(&glass, &out, vec3_scale(out.n, -1), lobes) == 0);
    check_lobes_against_samples(t, &glass, &out, at_60, 1);
    check_lobes_against_samples(t, &glass, &in, frame_direction(&in, 0.9, 0.5), 2);
    check_lobes_against_samples(t, &glass, &in, beyond_critical, 3);
    check_lobes_against_samples(t, &mirror, &out, at_60, 4);
}

void test_brdf_glass(struct check *t)
{
    RUN_TEST(t, test_brdf_glass_optics);
    RUN_TEST(t, test_coloured_glass);
    RUN_TEST(t, test_brdf_delta_lobes);
}
