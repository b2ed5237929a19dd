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

/* Sobol's dimension with primitive polynomial x^degree + ... + 1, whose middle
 * coefficients are the bits of a (highest first), and initial direction numbers m[0..degree-1]:
 * column k (k = 1, 2, ...) of its generator matrix is m_k / 2^k, where for k > degree
 * m_k = m_(k-degree) XOR 2^degree m_(k-degree) XOR (XOR over j < degree of a_j 2^j m_(k-j)),
 * a_j the coefficient of x^(degree-j). */
static uint32_t sobol_dimension(uint32_t i, int degree, uint32_t a, const uint32_t *m_initial)
{
    uint32_t m[32], result = 0;
    for (int k = 0; k < 32 && i != 0; k++, i >>= 1) {
        if (k < degree)
            m[k] = m_initial[k];
        else {
            m[k] = m[k - degree] ^ (m[k - degree] << degree);
            for (int j = 1; j < degree; j++)
                if ((a >> (degree - 1 - j)) & 1u)
                    m[k] ^= m[k - j] << j;
        }
        if (i & 1u)
            result ^= m[k] << (31 - k);
    }
    return result;
}

void sequence02_lens_point(uint32_t i, uint32_t shift_x, uint32_t shift_y, double *x,
                           double *y)
{
    static const uint32_t third[2] = {1, 3}, fourth[3] = {1, 3, 1};
    const double two_to_minus_32 = 1.0 / 4294967296.0;
    *x = (double)(sobol_dimension(i, 2, 1, third) ^ shift_x) * two_to_minus_32;
    *y = (double)(sobol_dimension(i, 3, 1, fourth) ^ shift_y) * two_to_minus_32;
}

void sequence02_point(uint32_t i, uint32_t shift_x, uint32_t shift_y, double *x, double *y)
{
    const double two_to_minus_32 = 1.0 / 4294967296.0;
    *x = (double)(van_der_corput(i) ^ shift_x) * two_to_minus_32;
    *y = (double)(sobol_second(i) ^ shift_y) * two_to_minus_32;
}

/* Laine and Karras's hash of x: each bit of the result depends only on the bits of x at
 * or below it, so applied to mirrored bits it scrambles each digit by the digits above. */
static uint32_t laine_karras(uint32_t x, uint32_t seed)
{
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

uint32_t sequence02_shuffled(uint32_t i, uint32_t seed)
{
    return van_der_corput(laine_karras(van_der_corput(i), seed));
}
