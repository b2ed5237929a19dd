/*
 * tests/bench/tte_fit.c -- the fit behind tte_fit.h.
 *
 * Weighted least squares of e = a x + c, x = 1 / t, with weights w_i = 1 / e_i^2. Without
 * weights the first checkpoints, whose errors are thousands of times the last ones, would
 * decide the fit alone, and c, a few hundred-thousandths, would be lost in their noise; the
 * weights make every row's relative miss count alike, as each checkpoint's relmse is about
 * as uncertain, relatively, as any other's. The weighted means x_m and e_m and the
 * deviations from them give a = sum w (x - x_m)(e - e_m) / sum w (x - x_m)^2 and
 * c = e_m - a x_m, without the cancellation of the raw sums' formula.
 */
#include "tte_fit.h"

#include <math.h>

/* The rule relmse - c ~ 1 / t through the row (t, relmse): what is left when no line can
 * be fitted. */
static struct tte_fit one_over_t(double t, double relmse, double c)
{
    struct tte_fit fit = {(relmse - c) * t, c, 0};
    return fit;
}

struct tte_fit tte_fit_rows_above(const double *t, const double *relmse, int n, double c)
{
    double sxx = 0, sxe = 0;
    for (int i = 0; i < n; i++) {
        double w = 1 / (relmse[i] * relmse[i]), x = 1 / t[i];
        sxx += w * x * x;
        sxe += w * x * (relmse[i] - c);
    }
    struct tte_fit fit = {sxe / sxx, c, 1};
    if (!(fit.a > 0)) /* error that does not fall with t: not pt's law */
        return one_over_t(t[n - 1], relmse[n - 1], c);
    return fit;
}

struct tte_fit tte_fit_rows(const double *t, const double *relmse, int n)
{
    double sw = 0, swx = 0, swe = 0;
    for (int i = 0; i < n; i++) {
        double w = 1 / (relmse[i] * relmse[i]);
        sw += w;
        swx += w / t[i];
        swe += w * relmse[i];
    }
    double x_m = swx / sw, e_m = swe / sw;
    double sxx = 0, sxe = 0;
    for (int i = 0; i < n; i++) {
        double w = 1 / (relmse[i] * relmse[i]), x = 1 / t[i];
        sxx += w * (x - x_m) * (x - x_m);
        sxe += w * (x - x_m) * (relmse[i] - e_m);
    }
    if (!(sxx > 0)) /* fewer than two distinct t: no slope to fit */
        return one_over_t(t[n - 1], relmse[n - 1], 0);
    struct tte_fit fit = {sxe / sxx, e_m - sxe / sxx * x_m, 1};
    /* The squared misses are a convex bowl in (a, c); with its floor at c < 0 the best
     * c >= 0 lies on the edge c = 0, where the fit is the line through the origin. */
    if (fit.c < 0)
        return tte_fit_rows_above(t, relmse, n, 0);
    if (!(fit.a > 0)) /* error that does not fall with t: not pt's law */
        return one_over_t(t[n - 1], relmse[n - 1], 0);
    return fit;
}

double tte_fit_error_at(const struct tte_fit *fit, double t)
{
    return fit->a / t + fit->c;
}

double tte_fit_time_to(const struct tte_fit *fit, double target)
{
    return target > fit->c ? fit->a / (target - fit->c) : INFINITY;
}
