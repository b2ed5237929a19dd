/*
 * tests/test_tte_fit.c -- the tte_fit room: the fit of the path tracer's error curve that
 * `make bench ONLY=tte` reads past pt's last checkpoint (tests/bench/tte_fit.h), on
 * synthetic checkpoints whose law is known.
 */
#include <math.h>

#include "bench/tte_fit.h"
#include "check.h"
#include "tests.h"

#define N_ROWS 12

/* Checkpoints as the bench takes them, after 1, 2, 4, ... samples a pixel (t0 seconds for
 * the first), with relmse exactly a / t + c. */
static void exact_rows(double a, double c, double t0, double *seconds, double *relmse)
{
    for (int i = 0; i < N_ROWS; i++) {
        seconds[i] = t0 * pow(2, i);
        relmse[i] = a / seconds[i] + c;
    }
}

/* truth: rows exactly on relmse = a / t + c (the Cornell box's a and c, and c = 0) give
 *   back a and c, and the times the law gives to errors past the last row.
 * tolerance: 1e-9 relative: rounding in sums of a dozen terms.
 * catches: the fit in t rather than 1 / t, the intercept and slope swapped, weights that
 *   do not cancel on exact data, the time to E read as a / E (the floor ignored). */
static void test_fit_recovers_law(struct check *t)
{
    static const double cases[][2] = {{0.0130, 0.000028}, {0.02, 0}, {5.0, 0.3}};
    for (int k = 0; k < 3; k++) {
        double a = cases[k][0], c = cases[k][1], seconds[N_ROWS], relmse[N_ROWS];
        exact_rows(a, c, 0.18, seconds, relmse);
        struct tte_fit fit = tte_fit_rows(seconds, relmse, N_ROWS);
        CHECK(t, fit.fitted);
        CHECK_CLOSE(t, fit.a, a, 1e-9 * a);
        CHECK_CLOSE(t, fit.c, c, 1e-9 * a);
        double target = c + a / 3000; /* past the last row, at 368.64 s */
        CHECK_CLOSE(t, tte_fit_time_to(&fit, target), 3000, 1e-6 * 3000);
        CHECK_CLOSE(t, tte_fit_error_at(&fit, 3000), target, 1e-9 * target);
    }
}

/* truth: an error at or below the floor c is never reached: time INFINITY, which the bench
 *   prints as extrapolated=unreachable with lower bounds from pt's last row.
 * tolerance: none.
 * catches: a / (E - c) with E <= c, a negative or infinite-but-printed time. */
static void test_floor_unreachable(struct check *t)
{
    double seconds[N_ROWS], relmse[N_ROWS];
    exact_rows(0.0130, 0.000028, 0.18, seconds, relmse);
    struct tte_fit fit = tte_fit_rows(seconds, relmse, N_ROWS);
    CHECK(t, isinf(tte_fit_time_to(&fit, 0.000028)));
    CHECK(t, isinf(tte_fit_time_to(&fit, 0.00002)));
    CHECK(t, isfinite(tte_fit_time_to(&fit, 0.00003)) && tte_fit_time_to(&fit, 0.00003) > 0);
}

/* truth: the fit's fallbacks (tte_fit.h). Rows on a / t + c with c < 0 (an error that
 *   would end below zero) are fitted with c held at 0, and still a > 0. Rows whose error
 *   grows with time, or a single row, give no a > 0: the rule relmse ~ 1 / t through the
 *   last row, a = its relmse x its seconds, c = 0, fitted = 0.
 * tolerance: 1e-9 relative.
 * catches: a negative floor kept, a fit with a <= 0 used, a division by zero on one row. */
static void test_fit_fallbacks(struct check *t)
{
    double seconds[N_ROWS], relmse[N_ROWS];
    exact_rows(0.02, -0.00001, 0.18, seconds, relmse); /* the last row still 4.4e-5 */
    struct tte_fit fit = tte_fit_rows(seconds, relmse, N_ROWS);
    CHECK(t, fit.fitted && fit.c == 0 && fit.a > 0);
    CHECK_CLOSE(t, tte_fit_time_to(&fit, 0.0001), fit.a / 0.0001, 1e-9 * fit.a / 0.0001);

    for (int i = 0; i < N_ROWS; i++)
        relmse[i] = 0.001 * (i + 1); /* growing: a < 0 */
    fit = tte_fit_rows(seconds, relmse, N_ROWS);
    CHECK(t, !fit.fitted && fit.c == 0);
    CHECK_CLOSE(t, fit.a, relmse[N_ROWS - 1] * seconds[N_ROWS - 1], 1e-9 * fit.a);

    double one_second = 2, one_relmse = 0.01;
    fit = tte_fit_rows(&one_second, &one_relmse, 1);
    CHECK(t, !fit.fitted && fit.c == 0);
    CHECK_CLOSE(t, fit.a, 0.02, 1e-12);
    CHECK_CLOSE(t, tte_fit_time_to(&fit, 0.001), 20, 1e-9);
}

/* truth: with the floor c given (the reference's variance image's), rows exactly on
 *   a / t + c give back a; rows on a / t + c' with c' != c give the a that puts the law
 *   through them as best it can, and the time it gives to an error reads the given floor:
 *   the specular box's case, whose checkpoints are all far above the floor.
 * tolerance: 1e-9 relative on exact rows.
 * catches: the floor ignored (a fitted to the whole relmse), c not kept in the fit, the
 *   weights' sums of the free fit reused. */
static void test_fit_above_given_floor(struct check *t)
{
    double seconds[N_ROWS], relmse[N_ROWS];
    exact_rows(0.438, 0.000121, 0.2, seconds, relmse);
    struct tte_fit fit = tte_fit_rows_above(seconds, relmse, N_ROWS, 0.000121);
    CHECK(t, fit.fitted && fit.c == 0.000121);
    CHECK_CLOSE(t, fit.a, 0.438, 1e-9 * 0.438);
    CHECK_CLOSE(t, tte_fit_time_to(&fit, 0.000121 + 0.438 / 5000), 5000, 1e-6 * 5000);
    struct tte_fit low = tte_fit_rows_above(seconds, relmse, N_ROWS, 0);
    CHECK(t, low.fitted && low.c == 0 && low.a > 0.438);
    CHECK(t, isinf(tte_fit_time_to(&fit, 0.0001)) && isfinite(tte_fit_time_to(&low, 0.0001)));
}

void test_tte_fit(struct check *t)
{
    RUN_TEST(t, test_fit_above_given_floor);
    RUN_TEST(t, test_fit_recovers_law);
    RUN_TEST(t, test_floor_unreachable);
    RUN_TEST(t, test_fit_fallbacks);
}
