/*
 * tests/brdf_cases.h -- what the material rooms share (test_brdf.c, test_brdf_glass.c,
 * test_brdf_conventions.c): the cases of every glossy model, the tilted shading frame they
 * are tested in, directions in it, single samples and sampled albedos.
 */
#ifndef PHOTON_TEST_BRDF_CASES_H
#define PHOTON_TEST_BRDF_CASES_H

#include <stdint.h>

#include "../src/scene/brdf.h"

#define SEED 20261123u /* every stream of the material rooms */

struct model_case {
    const char *name;
    struct material m;
    int albedo_exact; /* brdf_albedo() exact; else it is an upper bound */
};

/* A material of kind with albedo (or reflectance) rho, isotropic, everything else zero. */
struct material material_of(enum material_kind kind, struct vec3 rho);

/* Modified Phong: diffuse kd, specular ks, exponent n (brdf_albedo() exact). */
struct model_case phong_case(const char *name, struct vec3 kd, struct vec3 ks, double n);

/* Schlick: colour, roughness r, isotropy p (brdf_albedo() exact for r = 1 alone). */
struct model_case schlick_case(const char *name, struct vec3 colour, double r, double p);

/* Every model with a non-delta part, with parameters from broad to very peaked,
 * anisotropic, black in a channel, and the scenes' (Jensen 1996: 0.1 and 0.6). */
int glossy_cases(struct model_case *cases);
#define MAX_CASES 16

/* A tilted normal, so that world-to-local conversion is exercised. */
struct shading_frame test_frame(enum transport transport);

/* The unit direction at cos(theta) from f->n and azimuth phi from f->t. */
struct vec3 frame_direction(const struct shading_frame *f, double cos_theta, double phi);

/* Whether a and b differ by at most rel of the largest magnitude of their components. */
int close_vec3(struct vec3 a, struct vec3 b, double rel);

/* Draws one sample with the given uniforms; returns brdf_sample()'s result. */
int sample_with(const struct material *m, const struct shading_frame *f, struct vec3 wo,
                double u0, double u1, double u2, struct brdf_sample *s);

/* The mean sample weight over n samples of stream key (failures count as 0) and five
 * standard errors of it, estimated from the same samples, per channel. */
void estimate_albedo(const struct material *m, const struct shading_frame *f,
                     struct vec3 wo, uint64_t key, long n, struct vec3 *mean,
                     struct vec3 *five_se);

/* a <= b + tolerance in every channel. */
int at_most(struct vec3 a, struct vec3 b, struct vec3 tolerance);

#endif
