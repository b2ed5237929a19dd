/*
 * tests/projection_fixtures.h -- what the projection-map rooms share (test_projection.c,
 * test_projection_cells.c): one seed for every trace and stream, the maps' settings, and
 * photons traced into a sink.
 */
#ifndef PHOTON_TEST_PROJECTION_FIXTURES_H
#define PHOTON_TEST_PROJECTION_FIXTURES_H

#include <stddef.h>
#include <stdint.h>

#include "../src/photon/projection_map.h"
#include "../src/photon/trace.h"

#define SEED 13 /* every trace and stream in the projection rooms */

/* Maps of the default resolution whose specular cells are raised by boost. */
struct projection_settings settings(double boost);

/* Traces n photons of pass `pass` from scene into sink, through pm when it is not NULL. */
void trace_into(const struct scene *scene, const struct projection_maps *pm, size_t n,
                uint64_t pass, unsigned store, const struct photon_sink *sink);

#endif
