/*
 * base/sequence02.c -- the shifted (0,2)-sequence (sequence02.h).
 */
#include "sequence02.h"

/* The radical inverse of i in base 2, as 32 bits after the binary point: i's bits
 * mirrored about the point. */
static uint32_t van_der_corput(uint32_t i)
{
    uint32_t mirrored = 0;
    for (int bit = 0; bit < 32; bit++, i >>= 1)
        mirrored = (mirrored << 1) | (i & 1u);
    return mirrored;
}

/* Sobol's second dimension: its generator matrix is Pascal's triangle mod 2, whose
 * columns are made by v <- v XOR (v >> 1) from the top bit. */
static uint32_t sobol_second(uint32_t i)
{
    uint32_t result = 0;
    for (uint32_t v = 1u << 31; i != 0; i >>= 1, v ^= v >> 1)
        if (i & 1u)
            result ^= v;
    return result;
}

void sequence02_point(uint32_t i, uint32_t shift_x, uint32_t shift_y, double *x, double *y)
{
    const double two_to_minus_32 = 1.0 / 4294967296.0;
    *x = (double)(van_der_corput(i) ^ shift_x) * two_to_minus_32;
    *y = (double)(sobol_second(i) ^ shift_y) * two_to_minus_32;
}
