/*
 * tests/bench/tte_fit.h -- the path tracer's error curve past its last checkpoint, for the
 * tte workload (bench_tte.c) to read pt's time to an error it did not reach.
 *
 * pt is unbiased, so the variance of its image falls as 1 / t, t its samples a pixel or
 * its seconds at a steady rate; but its relmse is measured against a reference that is
 * itself a finite render, whose own noise the error never falls below. So
 * relmse(t) = a / t + c: a is pt's variance times t, c the reference's noise floor. c is
 * best read off the reference's variance image (its expected relmse against the truth);
 * a fit of pt's checkpoints then gives a alone. Where no variance image exists, the fit
 * gives both, though checkpoints whose a / t is far above c place c poorly. pt reaches an
 * error E at t = a / (E - c) when E > c, and never when E <= c. The functions take t in
 * whatever unit the rows give it.
 */
#ifndef PHOTON_TTE_FIT_H
#define PHOTON_TTE_FIT_H

/* relmse(t) = a / t + c. */
struct tte_fit {
    double a, c; /* a > 0, c >= 0                                                         */
    int fitted;  /* 1: the least-squares fit of the rows; 0: it failed (fewer than two
                    distinct t, or a <= 0), so the rule relmse ~ 1 / t through the last
                    row: a = its relmse minus c times its t                              */
};

/* The fit of the n rows (t[i] > 0, relmse[i] > 0; n >= 1) with c given (>= 0, below the
 * last row's relmse): a by least squares in x = 1 / t, each row weighted by
 * 1 / relmse[i]^2. */
struct tte_fit tte_fit_rows_above(const double *t, const double *relmse, int n, double c);

/* The fit of the n rows (t[i] > 0, relmse[i] > 0; n >= 1) by least squares in x = 1 / t,
 * each row weighted by 1 / relmse[i]^2 (its relative error counts), with c held at 0 when
 * the free fit puts it below. */
struct tte_fit tte_fit_rows(const double *t, const double *relmse, int n);

/* The fit's relmse at t > 0. */
double tte_fit_error_at(const struct tte_fit *fit, double t);

/* The fit's t to reach relmse target: a / (target - c), or INFINITY when target <= c (the
 * reference's own noise: no time reaches it). */
double tte_fit_time_to(const struct tte_fit *fit, double target);

#endif
