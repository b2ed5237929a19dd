/*
 * tests/bench/tte_fit.h -- the path tracer's error curve past its last checkpoint, for the
 * tte workload (bench_tte.c) to read pt's time to an error it did not reach.
 *
 * pt is unbiased, so the variance of its image falls as 1 / t, t its samples a pixel or
 * its seconds at a steady rate; but its relmse is measured against a reference that is
 * itself a finite render, whose own noise the error never falls below. So
 * relmse(t) = a / t + c: a is pt's variance times t, c the reference's noise floor. A fit
 * of pt's checkpoints gives a and c; pt reaches an error E at t = a / (E - c) when E > c,
 * and never when E <= c. The functions take t in whatever unit the rows give it.
 */
#ifndef PHOTON_TTE_FIT_H
#define PHOTON_TTE_FIT_H

/* relmse(t) = a / t + c. */
struct tte_fit {
    double a, c; /* a > 0, c >= 0                                                         */
    int fitted;  /* 1: the least-squares fit of the rows; 0: it failed (fewer than two
                    distinct t, or a <= 0), so the rule relmse ~ 1 / t through the last
                    row: a = its relmse times its t, c = 0                                */
};

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
