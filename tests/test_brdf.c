/*
 * tests/test_brdf.c -- the material models (scene/brdf.h): every sampler against its own
 * pdf and evaluation, reciprocity, and energy (albedos at most one, the white furnace).
 * Glass's optics and the delta lobes are test_brdf_glass.c's, what every model keeps at
 * its edges test_brdf_conventions.c's; the cases are brdf_cases.h's.
 *
 * The glossy lobes are integrated on a grid of directions centred on wo's mirror
 * direction a: polar angle theta' about a, in rows uniform in s with theta' = 2 pi s^2
 * up to pi / 2 (rows crowd where the lobes peak) and linear beyond, and azimuth phi'
 * about a. Each row is clipped exactly to the visible arc, the phi' where wi . n > 0, so
 * the horizon, where pdf and f jump to zero, never falls inside a quadrature cell, and
 * theta' = pi / 2, where Phong's lobe ends, is a row boundary. The same (s, phi') cells,
 * grouped, are the chi-square bins.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/base/rng.h"
#include "../src/scene/brdf.h"
#include "brdf_cases.h"
#include "tests.h"

#define GRID_ROWS 300  /* rows in s (see theta_of_s)                               */
#define BIN_ROWS 20    /* chi-square bins in s; GRID_ROWS / BIN_ROWS rows each     */
#define BIN_COLS 16    /* chi-square bins in phi'                                  */
#define COL_POINTS 12  /* midpoints per visible piece of a (row, bin column) cell  */
#define N_BINS (BIN_ROWS * BIN_COLS)
/* Error of the grid's integrals, measured on the closed forms (Lambert, Phong at normal
 * incidence, Phong's albedo quadrature): below 5e-5; the bound leaves room. */
#define GRID_TOL 2e-4
/* Upper 1e-4 point of the standard normal: the chi-square threshold's z. */
#define Z_1E4 3.719

static int close_rel(double a, double b, double rel)
{
    return fabs(a - b) <= rel * fmax(fabs(a), fabs(b));
}

/* The frame about wo's mirror direction a: u in the plane of a and n, towards n;
 * wi . n = cos_a cos(theta') + cos_u sin(theta') cos(phi') with cos_a = a . n >= 0
 * and cos_u = u . n >= 0. */
struct lobe_frame {
    struct vec3 a, u, v;
    double cos_a, cos_u;
};

static struct lobe_frame lobe_frame_of(const struct shading_frame *f, struct vec3 wo)
{
    struct lobe_frame lf;
    lf.a = vec3_sub(vec3_scale(f->n, 2.0 * vec3_dot(wo, f->n)), wo);
    struct vec3 towards_n = vec3_sub(f->n, vec3_scale(lf.a, vec3_dot(f->n, lf.a)));
    lf.u = vec3_length(towards_n) > 1e-9 ? vec3_normalize(towards_n) : f->t;
    lf.v = vec3_cross(lf.a, lf.u);
    lf.cos_a = vec3_dot(lf.a, f->n);
    lf.cos_u = vec3_dot(lf.u, f->n);
    return lf;
}

static struct vec3 lobe_direction(const struct lobe_frame *lf, double theta, double phi)
{
    return vec3_add(vec3_scale(lf->a, cos(theta)),
                    vec3_add(vec3_scale(lf->u, sin(theta) * cos(phi)),
                             vec3_scale(lf->v, sin(theta) * sin(phi))));
}

/* The grid's polar angle about a: 2 pi s^2 for s <= 1/2, then linear up to pi at s = 1,
 * and its inverse. */
static double theta_of_s(double s)
{
    return s <= 0.5 ? 2.0 * PI * s * s : PI * (s - 0.5) + 0.5 * PI;
}

static double s_of_theta(double theta)
{
    return theta <= 0.5 * PI ? sqrt(theta / (2.0 * PI)) : (theta - 0.5 * PI) / PI + 0.5;
}

/* Half-width of the visible arc of the row at theta': 0 if none of it, pi if all. */
static double visible_half_width(const struct lobe_frame *lf, double theta)
{
    double along = lf->cos_a * cos(theta), across = lf->cos_u * sin(theta);
    if (!(across > 1e-15))
        return along > 0 ? PI : 0.0;
    double kappa = -along / across;
    return kappa >= 1 ? 0.0 : kappa <= -1 ? PI : acos(kappa);
}

struct lobe_grid {
    double mass[N_BINS]; /* integral of brdf_pdf over each bin's visible part   */
    double total;        /* their sum: the probability of a non-delta sample      */
    struct vec3 albedo;  /* integral of brdf_eval cos_i over the hemisphere       */
};

/* One visible piece [lo, hi] of a row's bin column, by COL_POINTS midpoints. */
static void integrate_piece(const struct material *m, const struct shading_frame *f,
                            struct vec3 wo, const struct lobe_frame *lf, double theta,
                            double d_theta, double lo, double hi, int bin, struct lobe_grid *g)
{
    double d_phi = (hi - lo) / COL_POINTS;
    for (int k = 0; k < COL_POINTS; k++) {
        struct vec3 wi = lobe_direction(lf, theta, lo + (k + 0.5) * d_phi);
        double cos_i = vec3_dot(wi, f->n), w = sin(theta) * d_theta * d_phi;
        if (cos_i <= 0)
            continue; /* rounding at the arc's ends */
        double p = brdf_pdf(m, f, wo, wi) * w;
        g->mass[bin] += p;
        g->total += p;
        g->albedo = vec3_add(g->albedo, vec3_scale(brdf_eval(m, f, wo, wi), cos_i * w));
    }
}

static void integrate_lobe(const struct material *m, const struct shading_frame *f,
                           struct vec3 wo, const struct lobe_frame *lf, struct lobe_grid *g)
{
    memset(g, 0, sizeof *g);
    for (int row = 0; row < GRID_ROWS; row++) {
        double s = (row + 0.5) / GRID_ROWS, theta = theta_of_s(s);
        double d_theta = (s <= 0.5 ? 4.0 * PI * s : PI) / GRID_ROWS;
        double half = visible_half_width(lf, theta);
        int bin_row = row / (GRID_ROWS / BIN_ROWS);
        for (int col = 0; col < BIN_COLS; col++) {
            double lo = fmax(-PI + 2.0 * PI * col / BIN_COLS, -half);
            double hi = fmin(-PI + 2.0 * PI * (col + 1) / BIN_COLS, half);
            if (hi > lo)
                integrate_piece(m, f, wo, lf, theta, d_theta, lo, hi,
                                bin_row * BIN_COLS + col, g);
        }
    }
}

static int bin_of(const struct lobe_frame *lf, struct vec3 wi)
{
    double theta = acos(fmax(-1.0, fmin(1.0, vec3_dot(wi, lf->a))));
    double phi = atan2(vec3_dot(wi, lf->v), vec3_dot(wi, lf->u));
    int row = (int)(s_of_theta(theta) * BIN_ROWS), col = (int)((phi + PI) / (2 * PI) * BIN_COLS);
    row = row < BIN_ROWS ? row : BIN_ROWS - 1;
    col = col < BIN_COLS ? col : BIN_COLS - 1;
    return row * BIN_COLS + col;
}

struct sample_stats {
    long observed[N_BINS + 1]; /* per bin; the last counts delta samples and failures */
    long n_non_delta;          /* samples from a non-delta lobe                      */
    long pdf_mismatches;       /* s.pdf != brdf_pdf(wo, s.wi)                         */
    long weight_mismatches;    /* s.weight != brdf_eval cos / pdf                     */
};

static void draw_samples(const struct material *m, const struct shading_frame *f, struct vec3 wo,
                         const struct lobe_frame *lf, uint64_t key, long n,
                         struct sample_stats *st)
{
    struct rng rng = rng_stream(SEED, STREAM_TEST, key, 0);
    memset(st, 0, sizeof *st);
    for (long i = 0; i < n; i++) {
        double u[3];
        struct brdf_sample s;
        u[0] = rng_uniform(&rng);
        u[1] = rng_uniform(&rng);
        u[2] = rng_uniform(&rng);
        if (!brdf_sample(m, f, wo, u, &s) || s.delta) {
            st->observed[N_BINS]++;
            continue;
        }
        st->n_non_delta++;
        st->observed[bin_of(lf, s.wi)]++;
        double pdf = brdf_pdf(m, f, wo, s.wi);
        struct vec3 fr = brdf_eval(m, f, wo, s.wi);
        st->pdf_mismatches += !close_rel(s.pdf, pdf, 1e-9);
        st->weight_mismatches +=
            !(pdf > 0) || !close_vec3(s.weight, vec3_scale(fr, vec3_dot(s.wi, f->n) / pdf), 1e-9);
    }
}

/* Pearson's statistic over the bins pooled in order until each pool expects at least 5
 * (pooling decided by expected counts alone keeps the statistic's distribution);
 * *df = pools - 1. */
static double pooled_chi_square(const double *expected, const long *observed, int n, int *df)
{
    double chi2 = 0.0, e = 0.0, o = 0.0, last_e = 0.0, last_o = 0.0;
    int pools = 0;
    for (int i = 0; i < n; i++) {
        e += expected[i];
        o += (double)observed[i];
        if (e >= 5.0) {
            chi2 += (o - e) * (o - e) / e;
            last_e = e;
            last_o = o;
            pools++;
            e = o = 0.0;
        }
    }
    if (pools > 0 && (e > 0 || o > 0)) { /* the remainder joins the last pool */
        chi2 -= (last_o - last_e) * (last_o - last_e) / last_e;
        chi2 += (last_o + o - last_e - e) * (last_o + o - last_e - e) / (last_e + e);
    }
    *df = pools - 1;
    return chi2;
}

/* Wilson & Hilferty's approximation to the chi-square quantile with df degrees of
 * freedom at standard normal point z. */
static double chi_square_quantile(int df, double z)
{
    double k = df, c = 1.0 - 2.0 / (9.0 * k) + z * sqrt(2.0 / (9.0 * k));
    return k * c * c * c;
}

/* Schlick's specular (delta) part, c = 1 - 4 r (1 - r) for r < 1/2 (Schlick 1994 Sec. 5). */
static double schlick_delta_part(const struct material *m)
{
    if (m->kind != MATERIAL_SCHLICK || m->roughness >= 0.5)
        return 0.0;
    return 1.0 - 4.0 * m->roughness * (1.0 - m->roughness);
}

/* The pdf's integral and f cos's integral (the albedo) against their closed forms. */
static void check_grid_against_closed_forms(struct check *t, const struct model_case *c,
                                            const struct shading_frame *f, struct vec3 wo,
                                            const struct lobe_grid *g)
{
    int normal = vec3_dot(wo, f->n) > 1 - 1e-12;
    if (c->m.kind == MATERIAL_LAMBERT || (c->m.kind == MATERIAL_SCHLICK && c->albedo_exact) ||
        (c->m.kind == MATERIAL_PHONG && normal))
        CHECK_CLOSE(t, g->total, 1.0, GRID_TOL);
    struct vec3 albedo = brdf_albedo(&c->m, f, wo);
    struct vec3 grid = vec3_add(g->albedo, vec3_scale(c->m.rho, schlick_delta_part(&c->m)));
    if (c->albedo_exact) {
        CHECK_CLOSE(t, grid.x, albedo.x, GRID_TOL);
        CHECK_CLOSE(t, grid.y, albedo.y, GRID_TOL);
        CHECK_CLOSE(t, grid.z, albedo.z, GRID_TOL);
    } else {
        CHECK(t, vec3_max_component(vec3_sub(grid, albedo)) <= GRID_TOL);
    }
    CHECK(t, vec3_max_component(grid) <= 1 + GRID_TOL);
}

/* One wo of test_brdf_pdf_matches_samples: grid, samples, and the four checks. */
static void check_lobe(struct check *t, const struct model_case *c,
                       const struct shading_frame *f, struct vec3 wo, uint64_t key)
{
    const long n = 40000;
    struct lobe_frame lf = lobe_frame_of(f, wo);
    struct lobe_grid g;
    struct sample_stats st;
    integrate_lobe(&c->m, f, wo, &lf, &g);
    draw_samples(&c->m, f, wo, &lf, key, n, &st);
    double p = (double)st.n_non_delta / n, se = sqrt(p * (1 - p) / n);
    CHECK(t, fabs(g.total - p) <= 5 * se + GRID_TOL);
    double expected[N_BINS + 1];
    for (int i = 0; i < N_BINS; i++)
        expected[i] = n * g.mass[i];
    expected[N_BINS] = n * fmax(0.0, 1.0 - g.total);
    int df;
    double chi2 = pooled_chi_square(expected, st.observed, N_BINS + 1, &df);
    CHECK(t, df < 1 || chi2 <= chi_square_quantile(df, Z_1E4));
    CHECK(t, st.pdf_mismatches == 0 && st.weight_mismatches == 0);
    check_grid_against_closed_forms(t, c, f, wo, &g);
    if (t->failures_in_test > 0 && t->reports_in_test <= 10)
        fprintf(stderr, "  %s, cos_o %.4f: pdf integral %.6f, sampled %.6f, chi2 %.1f (df %d)\n",
                c->name, vec3_dot(wo, f->n), g.total, p, chi2, df);
}

/* truth: the sampler's own claims. (1) brdf_pdf integrates over the hemisphere to the
 *   probability that brdf_sample() returns a non-delta direction: 1 for Lambert and for
 *   Phong at normal incidence (closed form), else the observed fraction of N = 40000
 *   samples within 5 binomial standard errors + GRID_TOL. (2) The samples' histogram over
 *   320 bins (plus one for delta samples and failures) matches N times the pdf's integral
 *   over each bin: pooled chi-square below its 1 - 1e-4 quantile, fixed seed. (3) Each
 *   sample's pdf equals brdf_pdf(wo, wi) and its weight brdf_eval cos / pdf, to 1e-9
 *   relative (the world-local round trip). (4) f cos integrates to brdf_albedo() where it
 *   is exact, to at most it where it is a bound, and to at most 1; GRID_TOL apart.
 *   Over wo at 0, 30, 60, 85 and 89.9 degrees.
 * catches: a lobe sampled about the wrong axis, a wrong exponent in a pdf (n vs n + 1),
 *   a Jacobian 1 / (4 wo . h) dropped, mixture weights that differ between sample and
 *   pdf, azimuth stretched the wrong way, cosine sampling that is not cos / pi, Phong's
 *   albedo in closed form wrong. */
static void test_brdf_pdf_matches_samples(struct check *t)
{
    static const double theta_deg[] = {0, 30, 60, 85, 89.9};
    struct model_case cases[MAX_CASES];
    int n_cases = glossy_cases(cases);
    struct shading_frame f = test_frame(TRANSPORT_IMPORTANCE);
    for (int c = 0; c < n_cases; c++) {
        for (int w = 0; w < 5; w++) {
            struct vec3 wo = frame_direction(&f, cos(theta_deg[w] * PI / 180), 0.7);
            check_lobe(t, &cases[c], &f, wo, (uint64_t)(c * 8 + w));
        }
    }
}

/* truth: Helmholtz reciprocity f(wo, wi) = f(wi, wo) (every model here is written in
 *   symmetric form, so the two evaluations agree to rounding: 1e-12 relative), over 2000
 *   random pairs per model, half of them with wo near grazing; f finite and >= 0.
 * catches: a 1 / sqrt(cos_o cos_i) made one-sided, Phong's alpha measured about wo's
 *   mirror in a form that is not symmetric, a masking term applied to one direction. */
static void test_brdf_reciprocity(struct check *t)
{
    struct model_case cases[MAX_CASES];
    int n_cases = glossy_cases(cases);
    struct shading_frame f = test_frame(TRANSPORT_RADIANCE);
    struct rng rng = rng_stream(SEED, STREAM_TEST, 1000, 0);
    for (int c = 0; c < n_cases; c++) {
        for (int i = 0; i < 2000; i++) {
            /* cos uniform in (0, 1], cubed half the time to reach grazing angles */
            double c1 = 1.0 - rng_uniform(&rng), c2 = 1.0 - rng_uniform(&rng);
            c1 = i % 2 ? c1 * c1 * c1 : c1;
            struct vec3 wo = frame_direction(&f, c1, 2 * PI * rng_uniform(&rng));
            struct vec3 wi = frame_direction(&f, c2, 2 * PI * rng_uniform(&rng));
            struct vec3 forward = brdf_eval(&cases[c].m, &f, wo, wi);
            struct vec3 backward = brdf_eval(&cases[c].m, &f, wi, wo);
            CHECK(t, vec3_is_finite(forward) && vec3_max_component(vec3_neg(forward)) <= 0);
            CHECK(t, close_vec3(forward, backward, 1e-12));
        }
    }
}

/* truth: energy conservation, directional albedo <= 1, estimated as the mean sample
 *   weight (N = 20000, per channel) over wo at 8 polar angles up to 89.9 degrees and 2
 *   azimuths; tolerance 5 standard errors estimated from the same samples, + 1e-6 for
 *   the rounding of constant weights. The same estimate equals brdf_albedo() within that
 *   where brdf_albedo() is exact, and is at most it where it is a bound.
 * catches: Ward's original 1 / sqrt(cos_i cos_o) (albedo grows without bound at grazing
 *   angles), Schlick's G(v) = v / (r - rv + v) (2.6 at cos_o = 0.01, r = 0.01), Phong
 *   without its (n + 2) / (2 pi) normalisation, a lobe weight not divided by its
 *   probability. */
static void test_brdf_albedo_at_most_one(struct check *t)
{
    static const double theta_deg[] = {0, 20, 40, 60, 75, 85, 89, 89.9};
    struct model_case cases[MAX_CASES];
    int n_cases = glossy_cases(cases);
    struct shading_frame f = test_frame(TRANSPORT_IMPORTANCE);
    for (int c = 0; c < n_cases; c++) {
        for (int w = 0; w < 16; w++) {
            struct vec3 wo = frame_direction(&f, cos(theta_deg[w / 2] * PI / 180), 1.3 * (w % 2));
            struct vec3 mean, tol, albedo = brdf_albedo(&cases[c].m, &f, wo);
            estimate_albedo(&cases[c].m, &f, wo, 2000 + (uint64_t)(c * 16 + w), 20000, &mean,
                            &tol);
            tol = vec3_add(tol, vec3(1e-6, 1e-6, 1e-6));
            CHECK(t, at_most(mean, vec3(1, 1, 1), tol) && at_most(mean, albedo, tol));
            CHECK(t, !cases[c].albedo_exact || at_most(albedo, mean, tol));
        }
    }
}

/* Every sample of m at wo, for 100 spread uniforms, has weight 1 within tolerance. */
static void check_unit_weights(struct check *t, const struct material *m,
                               const struct shading_frame *f, struct vec3 wo, double tolerance)
{
    for (int i = 0; i < 100; i++) {
        struct brdf_sample s;
        int ok = sample_with(m, f, wo, (i + 0.5) / 100, (i * 37 % 100) / 100.0,
                             (i * 61 % 100) / 100.0, &s);
        CHECK(t, ok && vec3_max_abs(vec3_sub(s.weight, vec3(1, 1, 1))) <= tolerance);
    }
}

/* Glass in photon transport: both lobes have weight 1, their probabilities sum to 1. */
static void check_glass_furnace(struct check *t, struct vec3 n, double cos_o)
{
    struct material glass = material_of(MATERIAL_GLASS, vec3_zero());
    glass.ior = 1.5;
    for (int front = 0; front <= 1; front++) {
        struct shading_frame f = shading_frame_from_normal(n, front, TRANSPORT_IMPORTANCE);
        struct vec3 wo = frame_direction(&f, cos_o, 0.4);
        struct brdf_sample r, s;
        CHECK(t, sample_with(&glass, &f, wo, 0.0, 0.5, 0.5, &r) && !r.transmitted);
        CHECK(t, sample_with(&glass, &f, wo, 0.999999, 0.5, 0.5, &s));
        CHECK(t, r.weight.x == 1 && s.weight.x == 1 && r.delta && s.delta);
        CHECK(t, !s.transmitted || fabs(r.pdf + s.pdf - 1.0) <= 2.3e-16);
    }
}

/* truth: the white furnace. A surface that reflects everything returns each sample with
 *   weight exactly 1 where the model's weight is constant: Lambert rho = 1, Schlick r = 0
 *   with C = 1, the mirror with rho = 1 (Schlick r = 1, C = 1, a Lambertian reached
 *   through the general f cos / pdf, to 1e-15), and glass under importance transport
 *   (reflection F / F, refraction (1 - F) / (1 - F)), whose two lobes' probabilities sum
 *   to 1 (1 ulp). Modified Phong with kd + ks = 1 is exactly energy conserving at normal
 *   incidence (its albedo kd + ks, so the mean weight is 1 within 5 SE) and loses energy
 *   away from it, its specular albedo falling roughly as cos_o: kd = 0.3, ks = 0.7,
 *   n = 20 keep 0.6504 at 60 degrees and 0.3968 at 85 (brdf_albedo(), itself checked by
 *   the grid in test_brdf_pdf_matches_samples; the mean weight must match it within 5 SE).
 * catches: cosine sampling whose pdf is not cos / pi, a lobe weight not divided by its
 *   probability, a radiance scaling 1 / eta^2 left in photon transport. */
static void test_brdf_white_furnace(struct check *t)
{
    static const double cos_o[] = {1.0, 0.7071, 0.0017, 1e-12};
    static const double tolerance[] = {0, 1e-15, 0, 0};
    struct shading_frame f = test_frame(TRANSPORT_IMPORTANCE);
    struct material white[4];
    white[0] = material_of(MATERIAL_LAMBERT, vec3(1, 1, 1));
    white[1] = schlick_case("", vec3(1, 1, 1), 1.0, 1.0).m;
    white[2] = schlick_case("", vec3(1, 1, 1), 0.0, 1.0).m;
    white[3] = material_of(MATERIAL_MIRROR, vec3(1, 1, 1));
    for (int w = 0; w < 4; w++) {
        for (int k = 0; k < 4; k++)
            check_unit_weights(t, &white[k], &f, frame_direction(&f, cos_o[w], 0.4),
                               tolerance[k]);
        check_glass_furnace(t, f.n, cos_o[w]);
    }
    struct material phong = phong_case("", vec3(0.3, 0.3, 0.3), vec3(0.7, 0.7, 0.7), 20).m;
    static const double theta_deg[] = {0, 60, 85}, albedo_of_theta[] = {1.0, 0.6504, 0.3968};
    for (int w = 0; w < 3; w++) {
        struct vec3 wo = frame_direction(&f, cos(theta_deg[w] * PI / 180), 0.4), mean, tol;
        estimate_albedo(&phong, &f, wo, 3000 + (uint64_t)w, 20000, &mean, &tol);
        double albedo = brdf_albedo(&phong, &f, wo).x;
        CHECK(t, fabs(mean.x - albedo) <= tol.x);
        CHECK_CLOSE(t, albedo, albedo_of_theta[w], w == 0 ? 1e-12 : 1e-4);
    }
}

void test_brdf(struct check *t)
{
    RUN_TEST(t, test_brdf_pdf_matches_samples);
    RUN_TEST(t, test_brdf_reciprocity);
    RUN_TEST(t, test_brdf_albedo_at_most_one);
    RUN_TEST(t, test_brdf_white_furnace);
}
