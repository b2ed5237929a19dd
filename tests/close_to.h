/*
 * tests/close_to.h -- a relative tolerance for the irradiance cache rooms (test_cache.c,
 * test_cache_lookup.c).
 */
#ifndef PHOTON_TEST_CLOSE_TO_H
#define PHOTON_TEST_CLOSE_TO_H

/* Whether a is within tolerance |b| of b. */
int close_to(double a, double b, double tolerance);

#endif
