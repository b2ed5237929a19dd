/*
 * base/sequence02.h -- the (0,2)-sequence in base 2, randomised by a digital shift.
 *
 * Point i is (van der Corput of i, Sobol's second dimension of i) (Kollig & Keller 2002,
 * "Efficient multidimensional sampling"). Its first 2^k points are a (0,k,2)-net: each
 * elementary interval [a/2^j, (a+1)/2^j) x [b/2^(k-j), (b+1)/2^(k-j)) holds exactly one
 * of them, for every j. Camera samples taken in this order are stratified after any
 * power-of-two number of samples, so a progressive render stopped at 1, 2, 4, ... samples
 * per pixel has them all stratified.
 *
 * XOR-ing each coordinate's 32 bits with a random word (a random digital shift) maps
 * elementary intervals onto elementary intervals, so the net property survives, and
 * makes every single point uniform on the 2^-32 grid: estimates stay unbiased.
 */
#ifndef PHOTON_SEQUENCE02_H
#define PHOTON_SEQUENCE02_H

#include <stdint.h>

/* Point i of the sequence shifted by (shift_x, shift_y), in [0, 1)^2. */
void sequence02_point(uint32_t i, uint32_t shift_x, uint32_t shift_y, double *x, double *y);

/* Sobol's third and fourth dimensions of point i (Joe & Kuo's direction numbers: the
 * primitive polynomials x^2 + x + 1 and x^3 + x + 1), shifted by (shift_x, shift_y), in
 * [0, 1)^2. With sequence02_point(i) as the first two, they are the first four dimensions
 * of Sobol's sequence, a (3,4)-sequence in base 2: its first 2^k points are a
 * (3,k,4)-net, each elementary box of volume 2^(3-k) in [0, 1)^4 holding exactly 8 of
 * them. A camera sample's lens point drawn from them is stratified jointly with its point
 * in the pixel; a second (0,2)-sequence with the same index would pair the two point for
 * point, and the lens point would follow the pixel point. */
void sequence02_lens_point(uint32_t i, uint32_t shift_x, uint32_t shift_y, double *x,
                           double *y);

/* The place in the sequence of the i-th point of its order shuffled by seed: a nested
 * uniform scramble of i's bits from the lowest up (Burley 2020, "Practical hash-based
 * Owen scrambling", Sec. 6, with the Laine-Karras hash). The first 2^k shuffled points
 * are an aligned block of 2^k points of the sequence, so still a (0,k,2)-net, but in an
 * order of their own. Two samplers that both step through their own (0,2)-sequence with
 * the same index (a pixel's camera samples and a light's samples, pass by pass) are
 * otherwise paired point for point: a digital shift alone moves a point, not its partner,
 * and the pairs then sit on a lattice in four dimensions instead of filling them. */
uint32_t sequence02_shuffled(uint32_t i, uint32_t seed);

#endif
