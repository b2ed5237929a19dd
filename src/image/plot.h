/*
 * image/plot.h -- `photon plot`: error against time from the renderer's --report CSV
 * files, drawn log-log as a plain SVG 1.1 file (definitions and layout in plot.c).
 */
#ifndef PHOTON_PLOT_H
#define PHOTON_PLOT_H

#include "../base/error.h"

/* Runs per plot: each has its own colour, marker and dash pattern (plot.c's styles). */
#define PLOT_MAX_SERIES 8

/* A logarithmic axis from 10^k_lo to 10^k_hi, in whole decades; k_lo < k_hi. */
struct log_axis {
    int k_lo, k_hi;
};

/* The smallest whole-decade range holding [lo, hi] (finite, 0 < lo <= hi); a range that
 * would be empty (lo = hi = a power of ten) is padded by one decade each way. */
struct log_axis log_axis_fit(double lo, double hi);

/* Reads the --report CSV files csv[0 .. n_csv - 1] and writes their plot to svg, whole
 * or not at all. Returns 0, or -1 with *err filled ("file:line: message") for bad input:
 * then nothing is written and an existing svg is left as it was. */
int plot_files(const char *const *csv, int n_csv, const char *svg, struct error *err);

/* `photon plot A.csv [B.csv ...] -o PLOT.svg`: argv[0] is "plot". Returns the exit
 * status: 0, or 2 for bad input (messages on stderr). */
int plot_command(int argc, char **argv);

#endif
