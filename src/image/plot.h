/*
 * image/plot.h -- `photon plot`: columns of numeric CSV files drawn as a plain SVG 1.1
 * file (definitions and layout in plot.c). By default error against time from the
 * renderer's --report files, log-log; with --linear, profiles such as `photon probe`'s.
 */
#ifndef PHOTON_PLOT_H
#define PHOTON_PLOT_H

#include "../base/error.h"
#include "../base/option_equals.h"

/* Runs per plot: each has its own colour, marker and dash pattern (plot.c's styles). */
#define PLOT_MAX_SERIES 8

/* What to draw: the column x across, each column y[i] up (one run per file and y column),
 * on logarithmic or linear axes. Titles NULL: derived from the column names. */
struct plot_spec {
    const char *x;
    const char *y[PLOT_MAX_SERIES];
    int n_y;                           /* 1 .. PLOT_MAX_SERIES                       */
    int linear;                        /* 0: log-log, for errors; 1: linear, profiles */
    const char *x_title, *y_title;
};

/* seconds across, relmse up, log-log: the plot of --report files. */
struct plot_spec plot_spec_errors(void);

/* A logarithmic axis from 10^k_lo to 10^k_hi, in whole decades; k_lo < k_hi. */
struct log_axis {
    int k_lo, k_hi;
};

/* The smallest whole-decade range holding [lo, hi] (finite, 0 < lo <= hi); a range that
 * would be empty (lo = hi = a power of ten) is padded by one decade each way. */
struct log_axis log_axis_fit(double lo, double hi);

/* A linear axis from lo to hi, both whole multiples of step, lo < hi, with a labelled
 * tick at every multiple of step in between. */
struct linear_axis {
    double lo, hi, step;
};

/* The axis holding [lo, hi] (finite, lo <= hi) with the smallest step of 1, 2 or 5 x 10^k
 * that is at least (hi - lo) / 8, its ends rounded out to multiples of it; a range that
 * would be empty is widened by half its value each way (by 1 at 0). */
struct linear_axis linear_axis_fit(double lo, double hi);

/* Reads the CSV files csv[0 .. n_csv - 1] and writes their plot as spec says to svg,
 * whole or not at all. Returns 0, or -1 with *err filled ("file:line: message") for bad
 * input: then nothing is written and an existing svg is left as it was. */
int plot_files(const char *const *csv, int n_csv, const struct plot_spec *spec,
               const char *svg, struct error *err);

/* `photon plot [--x COL] [--y COL]... [--linear] [--x-title T] [--y-title T] A.csv
 * [B.csv ...] -o PLOT.svg`: argv[0] is "plot". Returns the exit status: 0, or 2 for bad
 * input (messages on stderr). */
int plot_command(int argc, char **argv);

/* Its options, for --NAME=VALUE (app/commands.h); a NULL name ends them. */
extern const struct option_arity plot_options[];

#endif
