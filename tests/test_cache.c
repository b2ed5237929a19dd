/*
 * tests/test_cache.c -- the irradiance cache's records (photon/irradiance_cache.h): the
 * strata, records against closed forms (constant and linear radiance, a glowing square),
 * and the bounds of a record's reach (modes/cache_pass.h). Lookups among records are
 * test_cache_lookup.c's.
 *
 * The gathers here are made by the tests themselves: a radiance field evaluated
 * per stratum in closed form, or rays cast from the point at an emitting square
 * and intersected analytically, so every truth is independent of the cache's
 * code.
 */
#include <math.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/modes/cache_pass.h"
#include "../src/photon/irradiance_cache.h"
#include "../src/scene/camera.h"
#include "close_to.h"
#include "tests.h"
#include "truths.h"

static struct vec3 local_to_world(struct vec3 v, struct vec3 t, struct vec3 b, struct vec3 n)
{
    return vec3_add(vec3_add(vec3_scale(t, v.x), vec3_scale(b, v.y)), vec3_scale(n, v.z));
}

/* ---- strata ---- */

/* Whether every direction made in a stratum of m x n lies in it, and is unit
 * with z > 0. */
static int strata_round_trip(int m, int n, struct rng *rng)
{
    int same = 1;
    for (int j = 0; j < m; j++) {
        for (int k = 0; k < n; k++) {
            for (int q = 0; q < 4; q++) {
                double u1 = 0.001 + 0.998 * rng_uniform(rng);
                double u2 = 0.001 + 0.998 * rng_uniform(rng);
                struct vec3 w = stratum_direction(m, n, j, k, u1, u2);
                int jj = -1, kk = -1;
                stratum_of(m, n, w, &jj, &kk);
                same = same && jj == j && kk == k && fabs(vec3_length(w) - 1) <= 1e-15 && w.z > 0;
            }
        }
    }
    return same;
}

/* truth: stratum_of() inverts stratum_direction(): a direction made in stratum
 * (j, k) lies in (j, k). u is kept 1e-3 of a stratum away from its edges, where
 * rounding may put a direction on either side. Plus the clamps: the pole is (0,
 * 0), the horizon is ring m - 1, a direction a hair below phi = 0 is sector n -
 * 1, and u1 just below 1 in the last ring still gives z > 0. tolerance: exact
 * indices; unit length to 1e-15. catches: theta spaced evenly instead of sin^2
 * theta, phi over pi instead of 2 pi in one of the two functions, an index off
 * by one, atan2's negative half not wrapped. */
static void test_strata_round_trip(struct check *t)
{
    static const int sizes[][2] = {{1, 1}, {1, 2}, {2, 1}, {3, 7}, {8, 16}, {64, 64}};
    struct rng rng = rng_stream(1, STREAM_TEST, 0, 0);
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        int m = sizes[s][0], n = sizes[s][1], j, k;
        CHECK(t, strata_round_trip(m, n, &rng));
        stratum_of(m, n, vec3(0, 0, 1), &j, &k);
        CHECK(t, j == 0 && k == 0);
        stratum_of(m, n, vec3(1, 0, 0), &j, &k);
        CHECK(t, j == m - 1 && k == 0);
        stratum_of(m, n, vec3(1, -1e-300, 0), &j, &k);
        CHECK(t, j == m - 1 && k == n - 1);
        CHECK(t, stratum_direction(m, n, m - 1, n - 1, 1 - ldexp(1, -53), 1 - ldexp(1, -53)).z > 0);
    }
}

/* truth: directions cosine-distributed over the hemisphere (pdf cos theta / pi)
 * have E[cos theta] = 2/3, E[x] = E[y] = 0, E[x^2] = E[y^2] = 1/4. Here u1, u2
 * run over the midpoints of a 64 x 64 grid in every stratum of 8 x 16, equally
 * weighted. tolerance: the grid is the midpoint rule in s = sin^2 theta with N
 * = 512 cells for cos theta = sqrt(1 - s), whose error is below N^-1.5 = 8.6e-5
 * (it comes from the last cell, where the root is not smooth); the phi means
 * are exact up to rounding (1e-12). catches: directions uniform in solid angle
 * (E[cos theta] = 1/2) or in theta (2/pi), phi over a half circle (E[y] = 4 /
 * (3 pi)). */
static void test_strata_are_cosine_distributed(struct check *t)
{
    const int m = 8, n = 16, grid = 64;
    double sum_z = 0, sum_x = 0, sum_y = 0, sum_x2 = 0, sum_y2 = 0;
    for (int i = 0; i < m * n * grid * grid; i++) { /* i = ((j n + k) grid + a) grid + b */
        int b = i % grid, a = i / grid % grid, k = i / (grid * grid) % n;
        int j = i / (grid * grid * n);
        struct vec3 w = stratum_direction(m, n, j, k, (a + 0.5) / grid, (b + 0.5) / grid);
        sum_z += w.z;
        sum_x += w.x;
        sum_y += w.y;
        sum_x2 += w.x * w.x;
        sum_y2 += w.y * w.y;
    }
    double count = (double)m * n * grid * grid;
    CHECK_CLOSE(t, sum_z / count, 2.0 / 3.0, pow(m * grid, -1.5));
    CHECK_CLOSE(t, sum_x / count, 0, 1e-12);
    CHECK_CLOSE(t, sum_y / count, 0, 1e-12);
    CHECK_CLOSE(t, sum_x2 / count, 0.25, 1e-12);
    CHECK_CLOSE(t, sum_y2 / count, 0.25, 1e-12);
}

/* ---- records ---- */

/* truth: radiance L the same from every direction gives E = pi L and no
 * gradient (Ward and Heckbert's sums of v_k over a full circle vanish, and
 * every difference between neighbouring strata is 0). R: all at distance 2
 * gives 2; every other stratum escaped gives 4 (half the sum of 1 / r); all
 * escaped gives r_max; distances below r_min or above r_max are clamped; a
 * distance of 0 gives r_min and finite gradients. tolerance: 1e-12 relative
 * (sums of at most 512 terms). catches: E missing pi or the 1 / (m n), an
 * arithmetic mean for R, an escaped stratum counted as distance 0, a division
 * by a zero distance, a single sector (n = 1) whose lone v_k makes a gradient
 * out of nothing. */
static void test_constant_radiance(struct check *t)
{
    static const int sizes[][2] = {{1, 1}, {1, 2}, {2, 1}, {3, 7}, {16, 32}};
    static struct stratum_sample samples[16 * 32];
    struct vec3 n = vec3_normalize(vec3(-1, 2, 2)), tangent, bitangent;
    vec3_frame(n, &tangent, &bitangent);
    struct vec3 l = vec3(0.25, 1, 3), p = vec3(1, 2, 3);
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        int m = sizes[s][0], n_phi = sizes[s][1], count = m * n_phi;
        for (int i = 0; i < count; i++) {
            samples[i].radiance = l;
            samples[i].distance = 2;
        }
        struct irradiance_record r =
            irradiance_record_make(p, tangent, bitangent, n, m, n_phi, samples, 0.01, 100);
        CHECK(t, close_to(r.e.x, PI * l.x, 1e-12) && close_to(r.e.y, PI * l.y, 1e-12) &&
                     close_to(r.e.z, PI * l.z, 1e-12));
        CHECK(t, r.r == 2 && vec3_length(vec3_sub(r.p, p)) == 0 && r.n.z == n.z);
        for (int c = 0; c < 3; c++)
            CHECK(t, vec3_length(r.grad_r[c]) <= 1e-12 * vec3_get(l, c) &&
                         vec3_length(r.grad_t[c]) == 0);
        for (int i = 0; i < count; i++)
            samples[i].distance = i % 2 == 0 ? 2 : INFINITY;
        if (count % 2 == 0)
            CHECK(
                t,
                irradiance_record_make(p, tangent, bitangent, n, m, n_phi, samples, 0.01, 100).r ==
                    4);
        for (int i = 0; i < count; i++)
            samples[i].distance = INFINITY;
        CHECK(t, irradiance_record_make(p, tangent, bitangent, n, m, n_phi, samples, 0.01, 100).r ==
                     100);
        CHECK(t, irradiance_record_make(p, tangent, bitangent, n, m, n_phi, samples, 0.01, 50).r ==
                     50);
        for (int i = 0; i < count; i++) {
            samples[i].distance = i == 0 ? 0 : 1e-4;
            samples[i].radiance = vec3_scale(l, i % 3); /* not constant: gradients */
        }
        struct irradiance_record near =
            irradiance_record_make(p, tangent, bitangent, n, m, n_phi, samples, 0.01, 100);
        CHECK(t, near.r == 0.01);
        for (int c = 0; c < 3; c++)
            CHECK(t, vec3_is_finite(near.grad_r[c]) && vec3_is_finite(near.grad_t[c]));
    }
}

/* The mean direction (local) over stratum (j, k) under the cosine-weighted
 * measure, in closed form: s = sin^2 theta and phi are uniform over the
 * stratum, so the means of sin theta = sqrt(s), cos theta = sqrt(1 - s), cos
 * phi and sin phi are integrals of powers and sines. */
static struct vec3 stratum_mean_direction(int m, int n, int j, int k)
{
    double s0 = (double)j / m, s1 = (j + 1.0) / m;
    double sin_theta = 2.0 / 3.0 * (pow(s1, 1.5) - pow(s0, 1.5)) / (s1 - s0);
    double cos_theta = 2.0 / 3.0 * (pow(1 - s0, 1.5) - pow(1 - s1, 1.5)) / (s1 - s0);
    double phi0 = 2 * PI * k / n, phi1 = 2 * PI * (k + 1) / n;
    return vec3(sin_theta * (sin(phi1) - sin(phi0)) / (phi1 - phi0),
                sin_theta * (cos(phi0) - cos(phi1)) / (phi1 - phi0), cos_theta);
}

/* A linear radiance field from infinitely far away, L_c(w) = a_c + b_c (w . d),
 * and its closed forms: E_c(n) = pi a_c + (2 pi / 3) b_c (d . n) (the
 * cosine-weighted integral of w over the hemisphere is (2 pi / 3) n), and the
 * rotational gradient (2 pi / 3) b_c (n x d), from dE = (2 pi / 3) b_c d . dn
 * with dn = (n_i x n) x n. */
struct linear_field {
    struct vec3 a, b; /* per channel, a >= |b| so that L >= 0 */
    struct vec3 d;    /* unit */
};

static struct vec3 linear_field_irradiance(const struct linear_field *f, struct vec3 n)
{
    return vec3_add(vec3_scale(f->a, PI), vec3_scale(f->b, 2 * PI / 3 * vec3_dot(f->d, n)));
}

/* A record gathered at p with normal n from the field: each stratum sees the
 * field's exact mean over it (the field is linear in w, so its mean is its
 * value at the mean direction) from infinitely far away. */
static struct irradiance_record linear_field_record(const struct linear_field *f, struct vec3 n,
                                                    int m, int n_phi)
{
    static struct stratum_sample samples[STRATA_MAX];
    struct vec3 tangent, bitangent;
    vec3_frame(n, &tangent, &bitangent);
    for (int j = 0; j < m; j++) {
        for (int k = 0; k < n_phi; k++) {
            struct vec3 w =
                local_to_world(stratum_mean_direction(m, n_phi, j, k), tangent, bitangent, n);
            samples[j * n_phi + k].radiance = vec3_madd(f->a, f->b, vec3_dot(w, f->d));
            samples[j * n_phi + k].distance = INFINITY;
        }
    }
    return irradiance_record_make(vec3(0, 0, 0), tangent, bitangent, n, m, n_phi, samples, 0.01,
                                  10);
}

/* truth: the linear field's closed forms (struct linear_field). E must match to
 *   rounding: the strata hold exact means. The rotational gradient integrates each
 * stratum exactly (irradiance_cache.c), so its only error is the radiance's change
 * within a stratum, which shrinks as 1 / m (measured shortfall along the true
 * direction: 2.4%, 0.35%, 0.11% at m = 4, 16, 64, i.e. at most 0.1 / m). Ward and
 * Heckbert's midpoint form, tan theta at each ring's middle, falls short by about
 * 0.44 / sqrt(m) (23%, 11.5%, 5.7%): the last ring's tan theta runs to infinity.
 * An environment at infinity moves with the point: no translational gradient, and
 * R = r_max.
 * tolerance: E 1e-12 relative; the gradient's shortfall within 0.15 / m (the
 * measured 0.1 / m with room; the midpoint form exceeds it at every m), its
 * component across the truth within 1e-3 (the shortfall has none; v_k a half
 * sector off would turn it by pi / n, 5% at n = 64). catches: a sign flip, v_k at
 * the sector's edge, a missing sin(pi / n), the midpoint form, the local gradient
 * put into world space with t and b swapped. */
static void test_rotational_gradient(struct check *t)
{
    struct linear_field f = {{2, 1, 0.3}, {1.5, -0.5, 0.3}, {0, 0, 0}};
    f.d = vec3_normalize(vec3(-2, 1, 0.5));
    struct vec3 n = vec3_normalize(vec3(1, 2, 3));
    static const int rings[] = {4, 16, 64};
    for (int s = 0; s < 3; s++) {
        int m = rings[s];
        struct irradiance_record r = linear_field_record(&f, n, m, 64);
        struct vec3 e = linear_field_irradiance(&f, n);
        CHECK(t, close_to(r.e.x, e.x, 1e-12) && close_to(r.e.y, e.y, 1e-12) &&
                     close_to(r.e.z, e.z, 1e-12));
        CHECK(t, r.r == 10);
        for (int c = 0; c < 3; c++) {
            struct vec3 truth = vec3_scale(vec3_cross(n, f.d), 2 * PI / 3 * vec3_get(f.b, c));
            double along = vec3_dot(r.grad_r[c], truth) / vec3_length2(truth);
            struct vec3 across = vec3_sub(r.grad_r[c], vec3_scale(truth, along));
            CHECK(t, along < 1 && 1 - along <= 0.15 / m);
            CHECK(t, vec3_length(across) <= 1e-3 * vec3_length(truth));
            CHECK(t, vec3_length(r.grad_t[c]) == 0);
        }
    }
}

/* truth: the closed form E(n') after turning the normal by 0.02 radians. A
 * cache holding the record made at n (m = n = 64) must return E(n) + (n x n') .
 * grad_r: exactly (to rounding) that, and within 3% of the true change E(n') -
 * E(n): the gradient's own shortfall at m = 64 is 0.11%, and the second-order
 * term of the turn, (1 - cos 0.02) / sin 0.02 = 1% of the first. catches: the
 * lookup applying (n x n_i) (the opposite sign), or not applying grad_r. */
static void test_rotational_gradient_in_lookup(struct check *t)
{
    struct linear_field f = {{2, 1, 0.3}, {1.5, -0.5, 0.3}, {0, 0, 0}};
    f.d = vec3_normalize(vec3(-2, 1, 0.5));
    struct vec3 n = vec3_normalize(vec3(1, 2, 3)), tangent, bitangent;
    vec3_frame(n, &tangent, &bitangent);
    struct irradiance_record r = linear_field_record(&f, n, 64, 64);
    struct aabb box = {{-1, -1, -1}, {1, 1, 1}};
    struct irradiance_cache *cache = irradiance_cache_create(box, 0.3);
    irradiance_cache_add(cache, &r);
    for (int axis = 0; axis < 2; axis++) {
        struct vec3 toward = axis == 0 ? bitangent : vec3_neg(tangent);
        struct vec3 turned = vec3_add(vec3_scale(n, cos(0.02)), vec3_scale(toward, sin(0.02)));
        struct vec3 e = vec3(-1, -1, -1);
        CHECK(t, irradiance_cache_lookup(cache, vec3(0, 0, 0), turned, 0.3, &e) == 1);
        struct vec3 before = linear_field_irradiance(&f, n);
        struct vec3 after = linear_field_irradiance(&f, turned);
        struct vec3 turn = vec3_cross(n, turned);
        for (int c = 0; c < 3; c++) {
            double predicted = vec3_get(r.e, c) + vec3_dot(turn, r.grad_r[c]);
            double change = vec3_get(after, c) - vec3_get(before, c);
            CHECK(t, close_to(vec3_get(e, c), predicted, 1e-12));
            CHECK(t, fabs(vec3_get(e, c) - vec3_get(after, c)) <= 0.03 * fabs(change));
        }
    }
    irradiance_cache_free(cache);
}

/* A square of radiance 1 parallel to the tangent plane of (p0, n) at height h
 * above it, spanning [x0, x1] x [y0, y1] along (t, b) from p0 + h n; everything
 * else is black. */
struct glowing_square {
    struct vec3 p0, t, b, n;
    double h, x0, x1, y0, y1;
};

static double square_irradiance(const struct glowing_square *sq, struct vec3 p)
{
    struct vec3 centre = vec3_madd(sq->p0, sq->n, sq->h), v[4];
    double x[4] = {sq->x0, sq->x1, sq->x1, sq->x0}, y[4] = {sq->y0, sq->y0, sq->y1, sq->y1};
    for (int i = 0; i < 4; i++)
        v[i] = vec3_add(centre, vec3_add(vec3_scale(sq->t, x[i]), vec3_scale(sq->b, y[i])));
    return polygon_irradiance(v, 4, p, sq->n, 1.0);
}

/* The distance along unit w from p (in the tangent plane) to the square, or
 * INFINITY. */
static double square_hit(const struct glowing_square *sq, struct vec3 p, struct vec3 w)
{
    double distance = sq->h / vec3_dot(w, sq->n); /* w . n > 0 */
    struct vec3 q = vec3_sub(vec3_madd(p, w, distance), sq->p0);
    double x = vec3_dot(q, sq->t), y = vec3_dot(q, sq->b);
    return x >= sq->x0 && x <= sq->x1 && y >= sq->y0 && y <= sq->y1 ? distance : INFINITY;
}

/* The record a final gather at p makes: rays ray x ray per stratum, on the
 * midpoints of a grid in (u1, u2); L_jk the fraction that hit, r_jk the nearest
 * hit; radii from r_min to 100. */
static struct irradiance_record square_record(const struct glowing_square *sq, struct vec3 p, int m,
                                              int n_phi, int rays, double r_min)
{
    static struct stratum_sample samples[STRATA_MAX];
    for (int j = 0; j < m; j++) {
        for (int k = 0; k < n_phi; k++) {
            int hits = 0;
            double nearest = INFINITY;
            for (int a = 0; a < rays * rays; a++) {
                struct vec3 w = stratum_direction(m, n_phi, j, k, (a / rays + 0.5) / rays,
                                                  (a % rays + 0.5) / rays);
                double d = square_hit(sq, p, local_to_world(w, sq->t, sq->b, sq->n));
                hits += d < INFINITY;
                nearest = fmin(nearest, d);
            }
            samples[j * n_phi + k].radiance = vec3((double)hits / (rays * rays), 0, 0);
            samples[j * n_phi + k].distance = nearest;
        }
    }
    return irradiance_record_make(p, sq->t, sq->b, sq->n, m, n_phi, samples, r_min, 100);
}

/* truth: Lambert's closed form for the square's irradiance (truths.c), and its
 *   derivatives along t and b by central differences of it (step 1e-5: error
 * ~1e-10). Three points: off to one side, under a corner, and on the square's
 * axis of symmetry (y0 = -y1 seen from p), where the derivative along b is 0 by
 * symmetry: the strata and the rays within them are mirror images across phi =
 * 0, so the gradient's b part must vanish to rounding. tolerance: E within
 * 0.5%: the rays are a midpoint grid of 256 x 256 cells in (sin^2 theta, phi)
 * over an indicator function, wrong only in the cells the square's outline cuts
 * (measured 0.03% to 0.08%). The gradient: Ward and Heckbert's estimate is
 * first order in the strata's size (relative errors measured 10%, 4.7%, 2.3%,
 * 0.9%, 0.4% at m = 4, 8, 16, 32, 64, n = 4m up to 256); at 64 x 64 it measured
 * 0.3% to 0.45% here, and 1.5% rejects every wrong form we tried: cos^2 theta
 * left out (about 60% off), max(r) for min(r) (30% to 45%), the sector term
 * left out (about 100%); u_k at the sector's edge instead of its middle
 * (Radiance's form) turns the ring term by pi / n and shows as 5% across the
 * axis of symmetry at n = 32, which the symmetric point checks to 1e-9.
 * catches: the above, and a world-space conversion with t and b swapped or the
 * gradient out of the tangent plane. */
/* The square of the gradient tests: tilted, 1 above the plane, off centre. */
static struct glowing_square test_square(void)
{
    struct glowing_square sq;
    sq.p0 = vec3(0.3, -0.2, 0.5);
    sq.n = vec3_normalize(vec3(0.2, -0.3, 1));
    vec3_frame(sq.n, &sq.t, &sq.b);
    sq.h = 1;
    sq.x0 = 0.2;
    sq.x1 = 1.4;
    sq.y0 = -0.3;
    sq.y1 = 0.9;
    return sq;
}

/* The three points of the gradient tests: off to one side, under a corner, and on the
 * square's axis of symmetry. */
static const double square_offsets[3][2] = {{0, 0}, {1.3, 0.8}, {-0.5, 0.3}};

static struct vec3 square_point(const struct glowing_square *sq, int i)
{
    return vec3_add(sq->p0, vec3_add(vec3_scale(sq->t, square_offsets[i][0]),
                                     vec3_scale(sq->b, square_offsets[i][1])));
}

/* The closed-form gradient of the square's irradiance at p along t and b, by central
 * differences of Lambert's formula (step 1e-5: error ~1e-10). */
static void square_gradient(const struct glowing_square *sq, struct vec3 p, double *dx,
                            double *dy)
{
    const double step = 1e-5;
    *dx = (square_irradiance(sq, vec3_madd(p, sq->t, step)) -
           square_irradiance(sq, vec3_madd(p, sq->t, -step))) / (2 * step);
    *dy = (square_irradiance(sq, vec3_madd(p, sq->b, step)) -
           square_irradiance(sq, vec3_madd(p, sq->b, -step))) / (2 * step);
}

static void test_translational_gradient(struct check *t)
{
    struct glowing_square sq = test_square();
    for (int i = 0; i < 3; i++) {
        struct vec3 p = square_point(&sq, i);
        struct irradiance_record r = square_record(&sq, p, 64, 64, 4, 1e-3);
        CHECK(t, close_to(r.e.x, square_irradiance(&sq, p), 0.005));
        double dx, dy;
        square_gradient(&sq, p, &dx, &dy);
        struct vec3 g = r.grad_t[0];
        double error = hypot(vec3_dot(g, sq.t) - dx, vec3_dot(g, sq.b) - dy);
        CHECK(t, error <= 0.015 * hypot(dx, dy));
        CHECK(t, fabs(vec3_dot(g, sq.n)) <= 1e-12 * vec3_length(g));
        if (i == 2)
            CHECK(t, fabs(vec3_dot(g, sq.b)) <= 1e-9 * vec3_length(g));
        CHECK(t, vec3_length(r.grad_t[1]) == 0 && vec3_length(r.grad_r[2]) == 0);
    }
}

/* truth: the closed-form E and gradient of the glowing square (above). Most of each
 *   point's strata see nothing, so the harmonic mean distance is several times the
 *   square's height (measured 7.3, 5.6 and 18.7), while E / |grad E| is 0.54 to 0.77:
 *   the record's R must be E / |grad E| of the closed forms, within 2% (E within 0.5% and
 *   the gradient within 1.5%, above; measured 0.4% to 0.5%). With r_min above that
 *   limit, R is r_min.
 * catches: the limit left out, E's luminance set against one channel's gradient or the
 *   reverse (only red is lit here: 0.2126 or 1 / 0.2126 off), the limit overriding r_min,
 *   E / |grad| inverted. */
static void test_gradient_limits_radius(struct check *t)
{
    struct glowing_square sq = test_square();
    for (int i = 0; i < 3; i++) {
        struct vec3 p = square_point(&sq, i);
        double dx, dy;
        square_gradient(&sq, p, &dx, &dy);
        double limit = square_irradiance(&sq, p) / hypot(dx, dy);
        struct irradiance_record r = square_record(&sq, p, 64, 64, 4, 1e-3);
        CHECK(t, close_to(r.r, limit, 0.02));
        CHECK(t, square_record(&sq, p, 64, 64, 4, 2 * limit).r == 2 * limit);
    }
}

/* truth: cache_pass.h's contract, computed by hand: a 90-degree camera 100 pixels high at
 *   the origin sees a pixel 2 tan 45 / 100 = 0.02 wide at distance 1, so at a point 10
 *   away, faced squarely, r_min = 1.5 x 0.2 / a; a surface turned 60 degrees from the
 *   camera doubles it, a grazing one is held at ten times; r_max is a fifth of the
 *   diagonal unless r_min is larger. The bound depends on the point and the camera alone,
 *   so a record made for a point seen in a mirror has the reach a direct view gives it.
 * tolerance: 1e-12 relative (a few roundings).
 * catches: the footprint taken from anything but the camera's distance to the point (the
 *   path's length, which once gave records seen in the mirror ball a reach of 37 cm), the
 *   slant ignored or not clamped, a instead of 1 / a, r_min = 0 at the camera's position
 *   (an assertion in irradiance_record_make(), reached by a scene with a mirror facing the
 *   camera squarely: tests/test_cli.c). */
static void test_record_radius_bounds(struct check *t)
{
    struct camera c;
    memset(&c, 0, sizeof c); /* a pinhole: no lens */
    c.from = vec3(0, 0, 0);
    c.at = vec3(0, 0, 1);
    c.up = vec3(0, 1, 0);
    c.fov = 90;
    camera_setup(&c, 100, 100);
    double r_min, r_max, a = 0.15, square = 1.5 * 0.2 / a;
    record_radius_bounds(&c, vec3(0, 0, 10), vec3(0, 0, -1), a, 1000, &r_min, &r_max);
    CHECK_CLOSE(t, r_min, square, 1e-12 * square);
    CHECK_CLOSE(t, r_max, 200, 1e-12 * 200);
    record_radius_bounds(&c, vec3(0, 0, 10), vec3(0, sqrt(0.75), -0.5), a, 1000, &r_min, &r_max);
    CHECK_CLOSE(t, r_min, 2 * square, 1e-12 * square);
    record_radius_bounds(&c, vec3(0, 0, 10), vec3(0, 1, 0), a, 10, &r_min, &r_max);
    CHECK_CLOSE(t, r_min, 10 * square, 1e-12 * square);
    CHECK(t, r_max == r_min); /* a fifth of the diagonal, 2, is below r_min */
    /* A path back through the camera's position (a mirror facing it squarely): no
     * footprint there, so the floor is the ray offset, 1e-9 x max(1, |p|) (geom/ray.h),
     * and irradiance_record_make()'s r_min > 0 holds. */
    record_radius_bounds(&c, c.from, vec3(0, 0, 1), a, 1000, &r_min, &r_max);
    CHECK(t, r_min == 1e-9 && r_max == 200);
    record_radius_bounds(&c, vec3(0, 0, 1e-30), vec3(0, 0, -1), a, 1000, &r_min, &r_max);
    CHECK(t, r_min == 1e-9);
}

void test_cache(struct check *t)
{
    RUN_TEST(t, test_strata_round_trip);
    RUN_TEST(t, test_strata_are_cosine_distributed);
    RUN_TEST(t, test_constant_radiance);
    RUN_TEST(t, test_rotational_gradient);
    RUN_TEST(t, test_rotational_gradient_in_lookup);
    RUN_TEST(t, test_translational_gradient);
    RUN_TEST(t, test_gradient_limits_radius);
    RUN_TEST(t, test_record_radius_bounds);
}
