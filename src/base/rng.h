/*
 * base/rng.h -- deterministic, counter-based random streams.
 *
 * Every random number in photon comes from a stream named by its purpose and its place
 * in the work: rng_stream(seed, STREAM_CAMERA, pixel, sample) or
 * rng_stream(seed, STREAM_PHOTON, pass, photon). A stream's numbers depend on those four
 * keys only, never on what was drawn before elsewhere, so the order in which pixels or
 * photons are processed cannot change a result, and a crop renders bit-identically to
 * the same window of the whole image.
 *
 * The key is hashed with the SplitMix64 finaliser (Steele, Lea, Flood 2014), and the
 * stream then steps as SplitMix64: a 64-bit counter advanced by the golden-ratio constant.
 */
#ifndef PHOTON_RNG_H
#define PHOTON_RNG_H

#include <stdint.h>

/* The purposes of streams; each value keys a family of streams disjoint from the others. */
enum stream {
    STREAM_CAMERA = 1,   /* index = pixel y * width + x of the whole image, sub = sample  */
    STREAM_PHOTON = 2,   /* index = pass, sub = photon number within the pass            */
    STREAM_CACHE = 3,    /* index = record or pixel, sub = sample: irradiance-cache work */
    STREAM_TEST = 4,     /* tests and benches                                            */
    STREAM_SCENE = 5,    /* procedural geometry (noise permutations)                      */
    STREAM_PIXEL = 6,    /* index = pixel: the digital shift of its camera samples       */
    STREAM_LIGHT = 7,    /* index = pixel, sub = hit point within it: the digital shifts of
                            its light samples, one per light (PPM's direct term)          */
    STREAM_DISC = 8      /* index = pixel: the shift and order of its disc probes (2009)  */
};

struct rng {
    uint64_t state; /* SplitMix64 counter */
};

struct rng rng_stream(uint64_t seed, enum stream purpose, uint64_t index, uint64_t sub);
uint64_t rng_next(struct rng *r);

/* Uniform double in [0, 1) with 53 random bits: never 1, so 1 - u is never 0. */
static inline double rng_uniform(struct rng *r)
{
    return (double)(rng_next(r) >> 11) * (1.0 / 9007199254740992.0);
}

/* u[0..n-1] = n draws of rng_uniform(r), u[0] first. A helper, not an initializer: in
 * {rng_uniform(r), rng_uniform(r), rng_uniform(r)} the order of the draws is unspecified
 * (C99 6.7.8), so which number lands in which slot could differ between compilers. */
void rng_uniforms(struct rng *r, double *u, int n);

#endif
