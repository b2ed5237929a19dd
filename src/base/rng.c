/*
 * base/rng.c -- SplitMix64 steps and the hashing of stream keys (see rng.h).
 */
#include "rng.h"

#define GOLDEN_GAMMA 0x9E3779B97F4A7C15u /* 2^64 / golden ratio, SplitMix64's increment */

/* The SplitMix64 output function: a bijection on 64 bits with full avalanche. */
static uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

uint64_t rng_next(struct rng *r)
{
    r->state += GOLDEN_GAMMA;
    return mix64(r->state);
}

/* Each key is folded in through mix64, so (seed, purpose, index, sub) tuples that differ
 * in any field start far apart in the 2^64 cycle. */
struct rng rng_stream(uint64_t seed, enum stream purpose, uint64_t index, uint64_t sub)
{
    struct rng r;
    uint64_t h = mix64(seed + GOLDEN_GAMMA);
    h = mix64(h ^ ((uint64_t)purpose * GOLDEN_GAMMA));
    h = mix64(h ^ (index + 0x632BE59BD9B4E019u));
    h = mix64(h ^ (sub + 0x8CB92BA72F3D8DD7u));
    r.state = h;
    return r;
}

void rng_uniforms(struct rng *r, double *u, int n)
{
    for (int k = 0; k < n; k++)
        u[k] = rng_uniform(r);
}
