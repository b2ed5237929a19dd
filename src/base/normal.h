/*
 * base/normal.h -- the standard normal distribution's two-sided critical value, which the
 * error images (a bound at a confidence) and photon compare's test (a level) both need.
 */
#ifndef PHOTON_NORMAL_H
#define PHOTON_NORMAL_H

/* Two-sided standard normal critical value: the z >= 0 with P(|Z| >= z) = p, that is
 * erfc(z / sqrt(2)) = p, for 0 < p <= 1 (z < 38.5 for every double p; accuracy in
 * normal.c: ~1e-15 for z < 7, 1.4e-14 at z = 37). */
double normal_critical_two_sided(double p);

#endif
