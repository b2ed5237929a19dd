/*
 * tests/trace_fixtures.h -- what the photon-tracing rooms share (test_trace_emission.c,
 * test_trace.c, test_trace_estimates.c, test_trace_photons_mode.c): one seed for every
 * trace, squares to build scenes of, a trace of n photons, and the tests' random streams.
 */
#ifndef PHOTON_TEST_TRACE_FIXTURES_H
#define PHOTON_TEST_TRACE_FIXTURES_H

#include <stddef.h>
#include <stdint.h>

#include "../src/base/rng.h"
#include "../src/photon/trace.h"
#include "../src/scene/scene.h"

#define SEED 11            /* every trace in the trace rooms */
#define TEST_MAX_DEPTH 1000 /* bounces: roulette ends paths long before */
#define RGBE_REL (1.0 / 255.5) /* photon.h: each channel within max(R, G, B) / 255.5 */

/* The square |x - cx|, |z - cz| <= half in the plane y, its front facing +y (up) or -y. */
void add_square(struct scene *scene, struct vec3 centre, double half, int up, int m);

/* n photons of pass `pass` traced from scene with SEED and TEST_MAX_DEPTH, storing the
 * classes in store (at most MAX_PHOTONS), aimed at targets unless it is NULL; a failed
 * trace's error is printed. */
struct photon_trace trace(const struct scene *scene, size_t n, unsigned store,
                          uint64_t pass, const struct emission_targets *targets);

/* The tests' stream (index, sub) of SEED. */
struct rng test_rng(uint64_t index, uint64_t sub);

#endif
