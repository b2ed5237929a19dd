/*
 * tests/truths.h -- closed forms and fixtures that several test rooms share: Lambert's
 * polygon irradiance (test_scene.c, test_pt.c) and loading a test scene (test_render.c,
 * test_pt.c).
 */
#ifndef PHOTON_TEST_TRUTHS_H
#define PHOTON_TEST_TRUTHS_H

#include "../src/scene/scene.h"

/* Lambert's formula for a polygon of constant radiance le seen from p with normal n
 * (light.h's convention): E = le / 2 * | sum_i beta_i n . normalize(r_i x r_i+1) |,
 * r_i = v_i - p, beta_i the angle between r_i and r_i+1. v: count corners in order. */
double polygon_irradiance(const struct vec3 *v, int count, struct vec3 p, struct vec3 n,
                          double le);

/* Loads and finishes the scene at path for width x height (0: the file's own size); the
 * caller frees it with scene_free. NULL, with the error printed, when it cannot be read. */
struct scene *load_test_scene(const char *path, int width, int height);

#endif
