/*
 * geom/noise.h -- Perlin's gradient noise in two dimensions and its fractal sum.
 *
 * noise2() is Perlin's improved noise (K. Perlin, "Improving Noise", SIGGRAPH 2002) in the
 * plane: the lattice gradient at each integer point is picked by an integer hash of the
 * point and a key instead of a permutation table, and blended with the quintic fade
 * 6t^5 - 15t^4 + 10t^3. It uses only +, *, floor and integer arithmetic, so a key gives the
 * same value, bit for bit, on every IEEE machine (built without FMA contraction).
 * fbm2() sums octaves of it: fractal Brownian motion (Musgrave, in Ebert et al., "Texturing
 * and Modeling", ch. 16).
 */
#ifndef PHOTON_NOISE_H
#define PHOTON_NOISE_H

#include <stdint.h>

/* 30 octaves take the finest lattice 2^29 times the first: beyond any grid we sample. */
#define NOISE_MAX_OCTAVES 30

/* Gradient noise at (x, y) for key: 0 at integer points, continuous with continuous first
 * and second derivatives, within [-1, 1] (unit gradients bound it by sqrt(2)/2, Perlin's
 * sqrt(N/4) for N = 2; the result is scaled by sqrt 2). |x|, |y| < 2^62. */
double noise2(double x, double y, uint64_t key);

/* Octave o (0-based) is noise2 at frequency 2^o with amplitude gain^o and its own key. */
struct fbm {
    int octaves;                      /* 1..NOISE_MAX_OCTAVES */
    double gain;                      /* amplitude ratio of successive octaves ("roughness") */
    double inv_sum;                   /* 1 / sum of gain^o: fbm2 stays within [-1, 1]    */
    uint64_t key[NOISE_MAX_OCTAVES];  /* from rng_stream(seed, STREAM_SCENE, o, 0)       */
};

/* octaves in 1..NOISE_MAX_OCTAVES and gain > 0 are the caller's to check. */
struct fbm fbm_make(uint64_t seed, int octaves, double gain);

/* sum_o gain^o noise2(2^o x, 2^o y, key_o) / sum_o gain^o, within [-1, 1]. */
double fbm2(const struct fbm *f, double x, double y);

#endif
