/*
 * geom/noise.c -- 2-D improved gradient noise and fractal Brownian motion (see noise.h).
 *
 * Lattice point (i, j) gets one of eight unit gradients, at multiples of 45 degrees, from
 * three bits of hash(key, i, j); the noise at (x, y) blends the four corner gradients'
 * linear ramps g . (x - i, y - j) with the fade curve, as Perlin 2002 does in 3-D.
 */
#include "noise.h"

#include <math.h>

#include "../base/rng.h"

#define SQRT_HALF 0.70710678118654752440 /* 1 / sqrt 2 */
#define SQRT_TWO 1.41421356237309504880

/* The SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijection of 64-bit words in which
 * every input bit flips each output bit with probability about 1/2. */
static uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* g . (dx, dy) for the gradient g hashed from lattice point (i, j) and key. Integers are
 * hashed as two's-complement 64-bit words (defined conversion to unsigned). */
static double gradient_ramp(int64_t i, int64_t j, uint64_t key, double dx, double dy)
{
    uint64_t h = mix64(mix64(key ^ (uint64_t)i) ^ (uint64_t)j) >> 61; /* 0..7 */
    switch (h) {
    case 0: return dx;
    case 1: return (dx + dy) * SQRT_HALF;
    case 2: return dy;
    case 3: return (dy - dx) * SQRT_HALF;
    case 4: return -dx;
    case 5: return -(dx + dy) * SQRT_HALF;
    case 6: return -dy;
    default: return (dx - dy) * SQRT_HALF;
    }
}

/* Perlin 2002: fade(t) = 6t^5 - 15t^4 + 10t^3, in Horner form. */
static double fade(double t)
{
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

static double lerp(double t, double a, double b)
{
    return a + t * (b - a);
}

double noise2(double x, double y, uint64_t key)
{
    double fx = floor(x), fy = floor(y);
    int64_t i = (int64_t)fx, j = (int64_t)fy; /* |x|, |y| < 2^62: representable */
    double dx = x - fx, dy = y - fy;          /* exact: Sterbenz, x and floor(x) are close */
    double n00 = gradient_ramp(i, j, key, dx, dy);
    double n10 = gradient_ramp(i + 1, j, key, dx - 1.0, dy);
    double n01 = gradient_ramp(i, j + 1, key, dx, dy - 1.0);
    double n11 = gradient_ramp(i + 1, j + 1, key, dx - 1.0, dy - 1.0);
    double u = fade(dx), v = fade(dy);
    return SQRT_TWO * lerp(v, lerp(u, n00, n10), lerp(u, n01, n11));
}

struct fbm fbm_make(uint64_t seed, int octaves, double gain)
{
    struct fbm f;
    f.octaves = octaves;
    f.gain = gain;
    double sum = 0, amplitude = 1;
    for (int o = 0; o < octaves; o++) {
        struct rng r = rng_stream(seed, STREAM_SCENE, (uint64_t)o, 0);
        f.key[o] = rng_next(&r);
        sum += amplitude;
        amplitude *= gain;
    }
    f.inv_sum = 1.0 / sum; /* sum >= 1: octave 0 has amplitude 1 */
    return f;
}

double fbm2(const struct fbm *f, double x, double y)
{
    double sum = 0, amplitude = 1, frequency = 1;
    for (int o = 0; o < f->octaves; o++) {
        sum += amplitude * noise2(x * frequency, y * frequency, f->key[o]);
        amplitude *= f->gain;
        frequency *= 2.0;
    }
    return sum * f->inv_sum;
}
