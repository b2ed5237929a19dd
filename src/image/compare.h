/*
 * image/compare.h -- error metrics between a test image and a reference, and the
 * `photon compare` command built on them.
 */
#ifndef PHOTON_COMPARE_H
#define PHOTON_COMPARE_H

#include "image.h"

/* The metrics `photon compare` prints; definitions in compare.c and the README. */
struct image_error {
    double rmse;   /* sqrt(mean over pixels and channels of (a - b)^2)                 */
    double relmse; /* mean over pixels and channels of (a - b)^2 / (b^2 + 1e-2)       */
    double psnr;   /* 10 log10(peak^2 / mse), peak = max over b's channels (>= 1e-30) */
    double maxerr; /* max over pixels and channels of |a - b|                          */
};

/* Metrics of test image a against reference b (same size, checked by the caller). */
struct image_error image_compare(const struct image *a, const struct image *b);

/* `photon compare A.pfm B.pfm [--diff OUT.ppm]`: argv[0] is "compare". Returns the exit
 * status: 0, or 2 for bad input (messages on stderr). */
int compare_command(int argc, char **argv);

#endif
