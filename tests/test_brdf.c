/*
 * tests/test_brdf.c -- the material models (scene/brdf.h): every sampler against its own
 * pdf and evaluation, reciprocity, energy, and the optics of glass.
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
#include "tests.h"

#define SEED 20261123u

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

struct model_case {
    const char *name;
    struct material m;
    int albedo_exact; /* brdf_albedo() exact; else it is an upper bound */
};

static struct material material_of(enum material_kind kind, struct vec3 rho)
{
    struct material m;
    memset(&m, 0, sizeof m);
    m.kind = kind;
    m.rho = rho;
    m.isotropy = 1.0;
    return m;
}

static struct model_case phong_case(const char *name, struct vec3 kd, struct vec3 ks,
                                    double n)
{
    struct model_case c = {name, material_of(MATERIAL_PHONG, kd), 1};
    c.m.rho_s = ks;
    c.m.exponent = n;
    return c;
}

static struct model_case ward_case(const char *name, struct vec3 rho_d, struct vec3 rho_s,
                                   double ax, double ay)
{
    struct model_case c = {name, material_of(MATERIAL_WARD, rho_d), 0};
    c.m.rho_s = rho_s;
    c.m.alpha_x = ax;
    c.m.alpha_y = ay;
    return c;
}

static struct model_case schlick_case(const char *name, struct vec3 colour, double r, double p)
{
    struct model_case c = {name, material_of(MATERIAL_SCHLICK, colour), r == 1};
    c.m.roughness = r;
    c.m.isotropy = p;
    return c;
}

/* Every model with a non-delta part, with parameters from broad to very peaked,
 * anisotropic, black in a channel, and the scenes' (Jensen 1996: 0.1 and 0.6). */
static int glossy_cases(struct model_case *cases)
{
    int n = 0;
    struct model_case lambert = {"lambert", material_of(MATERIAL_LAMBERT, vec3(0.8, 0.5, 0.2)),
                                 1};
    cases[n++] = lambert;
    cases[n++] = phong_case("phong n=10", vec3(0.5, 0.3, 0.2), vec3(0.4, 0.4, 0.4), 10);
    cases[n++] = phong_case("phong n=1000", vec3(0, 0, 0), vec3(1, 1, 1), 1000);
    cases[n++] = phong_case("phong n=1", vec3(0.2, 0.2, 0.2), vec3(0.7, 0.0, 0.7), 1);
    cases[n++] = phong_case("phong n=0", vec3(0.1, 0.1, 0.1), vec3(0.9, 0.9, 0.9), 0);
    cases[n++] = ward_case("ward 0.05/0.3", vec3(0.2, 0.2, 0.2), vec3(0.7, 0.7, 0.7), 0.05, 0.3);
    cases[n++] = ward_case("ward 0.2", vec3(0, 0, 0), vec3(1, 1, 1), 0.2, 0.2);
    cases[n++] = ward_case("ward 0.5", vec3(0.5, 0.2, 0.0), vec3(0.4, 0.4, 0.4), 0.5, 0.5);
    cases[n++] = schlick_case("schlick r=0.1", vec3(0.8, 0.8, 0.6), 0.1, 1.0);
    cases[n++] = schlick_case("schlick r=0.6", vec3(0.7, 0.6, 0.4), 0.6, 1.0);
    cases[n++] = schlick_case("schlick r=0.5 p=0.2", vec3(1, 1, 1), 0.5, 0.2);
    cases[n++] = schlick_case("schlick r=0.02", vec3(0.9, 0.9, 0.9), 0.02, 1.0);
    cases[n++] = schlick_case("schlick r=1", vec3(0.6, 0.6, 0.6), 1.0, 1.0);
    return n;
}
#define MAX_CASES 16

/* A tilted normal, so that world-to-local conversion is exercised. */
static struct shading_frame test_frame(enum transport transport)
{
    return shading_frame_from_normal(vec3_normalize(vec3(0.3, -0.5, 0.8)), 1, transport);
}

/* The unit direction at cos(theta) from f->n and azimuth phi from f->t. */
static struct vec3 frame_direction(const struct shading_frame *f, double cos_theta, double phi)
{
    double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    return vec3_add(vec3_add(vec3_scale(f->t, sin_theta * cos(phi)),
                             vec3_scale(f->b, sin_theta * sin(phi))),
                    vec3_scale(f->n, cos_theta));
}

static int close_rel(double a, double b, double rel)
{
    return fabs(a - b) <= rel * fmax(fabs(a), fabs(b));
}

static int close_vec3(struct vec3 a, struct vec3 b, double rel)
{
    double scale = fmax(vec3_max_abs(a), vec3_max_abs(b));
    return vec3_max_abs(vec3_sub(a, b)) <= rel * scale;
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

/* Draws one sample with the given uniforms; returns brdf_sample()'s result. */
static int sample_with(const struct material *m, const struct shading_frame *f, struct vec3 wo,
                       double u0, double u1, double u2, struct brdf_sample *s)
{
    double u[3];
    u[0] = u0;
    u[1] = u1;
    u[2] = u2;
    return brdf_sample(m, f, wo, u, s);
}

/* The mean sample weight over n samples of stream key (failures count as 0) and five
 * standard errors of it, estimated from the same samples, per channel. */
static void estimate_albedo(const struct material *m, const struct shading_frame *f,
                            struct vec3 wo, uint64_t key, long n, struct vec3 *mean,
                            struct vec3 *five_se)
{
    struct rng rng = rng_stream(SEED, STREAM_TEST, key, 0);
    struct vec3 sum = vec3_zero(), sum2 = vec3_zero();
    for (long i = 0; i < n; i++) {
        struct brdf_sample s;
        double u0 = rng_uniform(&rng), u1 = rng_uniform(&rng);
        if (!sample_with(m, f, wo, u0, u1, rng_uniform(&rng), &s))
            continue;
        sum = vec3_add(sum, s.weight);
        sum2 = vec3_add(sum2, vec3_mul(s.weight, s.weight));
    }
    *mean = vec3_scale(sum, 1.0 / n);
    struct vec3 var = vec3_max(vec3_sub(vec3_scale(sum2, 1.0 / n), vec3_mul(*mean, *mean)),
                               vec3_zero());
    *five_se = vec3(5 * sqrt(var.x / n), 5 * sqrt(var.y / n), 5 * sqrt(var.z / n));
}

/* a <= b + tolerance in every channel. */
static int at_most(struct vec3 a, struct vec3 b, struct vec3 tolerance)
{
    return vec3_max_component(vec3_sub(a, vec3_add(b, tolerance))) <= 0;
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

/* truth: a colour filter T on refraction, by hand: every refracted sample's weight is
 *   T (times 1 / eta^2 for radiance), every reflected one's white; the albedo is
 *   F + (1 - F) T, at normal incidence 0.04 + 0.96 T (F = 0.04 for index 1.5, Hecht),
 *   and brdf_albedo() matches the mean weight of 20,000 samples within 5 SE at 0, 60 and
 *   85 degrees, from both sides (beyond the critical angle inside, F = 1: white).
 * tolerance: 1e-12 for closed forms; 5 standard errors for the sampled means.
 * catches: the filter applied to reflection too, or not at all, or as its complement
 *   (the absorption), the albedo left at 1 for coloured glass, Fresnel taken from the
 *   wrong side. */
static void test_coloured_glass(struct check *t)
{
    struct material glass = material_of(MATERIAL_GLASS, vec3_zero());
    glass.ior = 1.5;
    glass.absorption = vec3(0.2, 0.5, 0.9); /* T = (0.8, 0.5, 0.1) */
    struct vec3 filter = vec3(0.8, 0.5, 0.1);
    static const double theta_deg[] = {0, 60, 85};
    for (int front = 0; front <= 1; front++) {
        struct shading_frame f = test_frame(TRANSPORT_IMPORTANCE);
        f = shading_frame_from_normal(f.n, front, TRANSPORT_IMPORTANCE);
        for (int w = 0; w < 3; w++) {
            struct vec3 wo = frame_direction(&f, cos(theta_deg[w] * PI / 180), 0.4);
            struct brdf_sample r, s;
            CHECK(t, sample_with(&glass, &f, wo, 0.0, 0.5, 0.5, &r) && !r.transmitted);
            CHECK(t, vec3_max_abs(vec3_sub(r.weight, vec3(1, 1, 1))) == 0);
            if (sample_with(&glass, &f, wo, 0.999999, 0.5, 0.5, &s) && s.transmitted)
                CHECK(t, vec3_max_abs(vec3_sub(s.weight, filter)) <= 1e-12);
            struct vec3 mean, tol, albedo = brdf_albedo(&glass, &f, wo);
            estimate_albedo(&glass, &f, wo, 4000 + (uint64_t)(3 * front + w), 20000, &mean,
                            &tol);
            CHECK(t, at_most(mean, albedo, tol) && at_most(albedo, mean, tol));
        }
    }
    struct shading_frame f = test_frame(TRANSPORT_IMPORTANCE);
    struct vec3 albedo = brdf_albedo(&glass, &f, f.n);
    struct vec3 normal = vec3_add(vec3(0.04, 0.04, 0.04), vec3_scale(filter, 0.96));
    CHECK(t, vec3_max_abs(vec3_sub(albedo, normal)) <= 1e-12);
    struct shading_frame radiance = test_frame(TRANSPORT_RADIANCE);
    struct brdf_sample s;
    CHECK(t, sample_with(&glass, &radiance, radiance.n, 0.999999, 0.5, 0.5, &s));
    CHECK(t, s.transmitted && vec3_max_abs(vec3_sub(s.weight, vec3_scale(filter, 1 / 2.25)))
                                  <= 1e-12);
}

/* One refraction from wo through glass (1.5) against Snell's law and 1 / eta^2. */
static void check_refraction(struct check *t, const struct shading_frame *f, double theta_deg,
                             double phi)
{
    struct material glass = material_of(MATERIAL_GLASS, vec3_zero());
    glass.ior = 1.5;
    double n_i = f->front ? 1.0 : 1.5, n_t = f->front ? 1.5 : 1.0;
    struct vec3 wo = frame_direction(f, cos(theta_deg * PI / 180), phi);
    struct brdf_sample s;
    CHECK(t, sample_with(&glass, f, wo, 0.999999, 0.5, 0.5, &s) && s.transmitted);
    double sin_i = vec3_length(vec3_cross(wo, f->n));
    double sin_t = vec3_length(vec3_cross(s.wi, f->n));
    CHECK_CLOSE(t, n_i * sin_i, n_t * sin_t, 1e-12);
    CHECK(t, vec3_dot(s.wi, f->n) < 0 && fabs(vec3_dot(s.wi, vec3_cross(wo, f->n))) < 1e-12);
    CHECK_CLOSE(t, vec3_length(s.wi), 1.0, 1e-15);
    CHECK_CLOSE(t, s.weight.x, (n_i / n_t) * (n_i / n_t), 1e-15);
}

/* truth: optics of a smooth dielectric, ior 1.5 (Hecht): F = ((1.5 - 1) / (1.5 + 1))^2 =
 *   0.04 at normal incidence from either side; from inside beyond the critical angle
 *   asin(1 / 1.5) = 41.8 degrees, reflection with probability 1 whatever u; a refracted
 *   direction obeys Snell's law n_i sin_i = n_t sin_t (1e-12), lies in the plane of wo
 *   and n, on the other side; its radiance weight is 1 / eta^2 = (n_i / n_t)^2. The lobe
 *   is reflection for u[0] < F, refraction above (F = 0.0892 at 60 degrees).
 * catches: eta inverted for the back side, Fresnel by Schlick's approximation (0.04 at
 *   normal incidence too, but 0.070 at 60 degrees where the Fresnel equations give
 *   0.0891867128), TIR refracting, the radiance scaling missing, the lobe chosen with
 *   a probability other than the pdf it reports. */
static void test_brdf_glass_optics(struct check *t)
{
    struct material glass = material_of(MATERIAL_GLASS, vec3_zero());
    glass.ior = 1.5;
    struct shading_frame out = test_frame(TRANSPORT_RADIANCE);
    struct shading_frame in = shading_frame_from_normal(out.n, 0, TRANSPORT_RADIANCE);
    struct brdf_sample s;
    CHECK(t, sample_with(&glass, &out, out.n, 0.0, 0.5, 0.5, &s) && !s.transmitted);
    CHECK_CLOSE(t, s.pdf, 0.04, 1e-15);
    CHECK(t, sample_with(&glass, &in, in.n, 0.0, 0.5, 0.5, &s) && !s.transmitted);
    CHECK_CLOSE(t, s.pdf, 0.04, 1e-15);
    CHECK(t, sample_with(&glass, &out, frame_direction(&out, 0.5, 1.0), 0.0, 0.5, 0.5, &s));
    CHECK_CLOSE(t, s.pdf, 0.0891867128, 1e-10); /* Fresnel equations, 60 degrees, 1.5 */
    CHECK(t, sample_with(&glass, &out, frame_direction(&out, 0.5, 1.0), 0.0891, 0.5, 0.5, &s));
    CHECK(t, !s.transmitted); /* u below F reflects, above it refracts */
    CHECK(t, sample_with(&glass, &out, frame_direction(&out, 0.5, 1.0), 0.0893, 0.5, 0.5, &s));
    CHECK(t, s.transmitted && fabs(s.pdf - (1 - 0.0891867128)) < 1e-10);
    for (int k = 0; k < 3; k++) { /* 45 degrees inside: beyond the critical angle */
        struct vec3 wo = frame_direction(&in, cos(45 * PI / 180), 2.0);
        CHECK(t, sample_with(&glass, &in, wo, k / 2.0 * 0.999999, 0.5, 0.5, &s));
        CHECK(t, !s.transmitted && s.pdf == 1 && s.weight.x == 1);
        struct vec3 mirror = vec3_sub(vec3_scale(in.n, 2 * vec3_dot(wo, in.n)), wo);
        CHECK(t, vec3_max_abs(vec3_sub(s.wi, mirror)) < 1e-15);
    }
    static const double theta_deg[] = {10, 30, 60, 89};
    for (int k = 0; k < 4; k++)
        check_refraction(t, &out, theta_deg[k], 0.3 + k);
    check_refraction(t, &in, 41.0, 1.0); /* just inside the critical angle */
    check_refraction(t, &in, 20.0, 5.0);
}

/* Each lobe of brdf_delta_lobes() against the mean weight brdf_sample() gives it. */
static void check_lobes_against_samples(struct check *t, const struct material *m,
                                        const struct shading_frame *f, struct vec3 wo,
                                        uint64_t key)
{
    struct brdf_sample lobes[2];
    int n_lobes = brdf_delta_lobes(m, f, wo, lobes);
    struct rng rng = rng_stream(SEED, STREAM_TEST, key, 0);
    const long n = 200000;
    double sum[2] = {0, 0}, sum2[2] = {0, 0};
    int same_direction = 1;
    for (long i = 0; i < n; i++) {
        struct brdf_sample s;
        double u0 = rng_uniform(&rng);
        if (!sample_with(m, f, wo, u0, 0.5, 0.5, &s))
            continue;
        int lobe = n_lobes == 2 && s.transmitted == lobes[1].transmitted;
        same_direction &= vec3_max_abs(vec3_sub(s.wi, lobes[lobe].wi)) == 0;
        sum[lobe] += s.weight.x;
        sum2[lobe] += s.weight.x * s.weight.x;
    }
    CHECK(t, same_direction);
    for (int k = 0; k < n_lobes; k++) {
        double mean = sum[k] / n, var = fmax(0.0, sum2[k] / n - mean * mean);
        CHECK_CLOSE(t, lobes[k].weight.x, mean, 5 * sqrt(var / n) + 1e-15);
        CHECK(t, lobes[k].pdf == 1 && lobes[k].delta);
    }
}

/* truth: the closed forms of the lobes (Hecht): for glass of index 1.5, reflection F (the
 *   Fresnel equations: 0.04 at normal incidence, 0.0891867128 at 60 degrees) and
 *   refraction (1 - F) / eta^2 for radiance; under total internal reflection one lobe of
 *   weight 1; the mirror one lobe of weight rho. Brute force: the mean weight of
 *   brdf_sample() per lobe over n random u equals that lobe's weight.
 * tolerance: 1e-10 for closed forms (the values are quoted to 10 digits); 5 standard
 *   errors for the sampled means (deterministic seed).
 * catches: the probability not folded in (glass's weights would be 1 and 1/eta^2), a lobe
 *   counted twice (the mirror, TIR), the refraction lobe missing, directions other than
 *   brdf_sample()'s. */
static void test_brdf_delta_lobes(struct check *t)
{
    struct material glass = material_of(MATERIAL_GLASS, vec3_zero());
    glass.ior = 1.5;
    struct shading_frame out = test_frame(TRANSPORT_RADIANCE);
    struct shading_frame in = shading_frame_from_normal(out.n, 0, TRANSPORT_RADIANCE);
    struct brdf_sample lobes[2];
    CHECK(t, brdf_delta_lobes(&glass, &out, out.n, lobes) == 2);
    CHECK_CLOSE(t, lobes[0].weight.x, 0.04, 1e-12);
    CHECK_CLOSE(t, lobes[1].weight.x, 0.96 / 2.25, 1e-12);
    CHECK(t, !lobes[0].transmitted && lobes[1].transmitted);
    struct vec3 at_60 = frame_direction(&out, 0.5, 1.0);
    CHECK(t, brdf_delta_lobes(&glass, &out, at_60, lobes) == 2);
    CHECK_CLOSE(t, lobes[0].weight.x, 0.0891867128, 1e-10);
    CHECK_CLOSE(t, lobes[1].weight.x, (1 - 0.0891867128) / 2.25, 1e-10);
    struct vec3 beyond_critical = frame_direction(&in, cos(45 * PI / 180), 2.0);
    CHECK(t, brdf_delta_lobes(&glass, &in, beyond_critical, lobes) == 1);
    CHECK(t, !lobes[0].transmitted && lobes[0].weight.x == 1);
    struct material mirror = material_of(MATERIAL_MIRROR, vec3(0.9, 0.5, 0.2));
    CHECK(t, brdf_delta_lobes(&mirror, &out, at_60, lobes) == 1);
    CHECK(t, vec3_max_abs(vec3_sub(lobes[0].weight, vec3(0.9, 0.5, 0.2))) == 0);
    CHECK(t, brdf_delta_lobes(&glass, &out, vec3_scale(out.n, -1), lobes) == 0);
    check_lobes_against_samples(t, &glass, &out, at_60, 1);
    check_lobes_against_samples(t, &glass, &in, frame_direction(&in, 0.9, 0.5), 2);
    check_lobes_against_samples(t, &glass, &in, beyond_critical, 3);
    check_lobes_against_samples(t, &mirror, &out, at_60, 4);
}

/* Every model once, the delta ones included. */
static int all_cases(struct model_case *cases)
{
    int n = glossy_cases(cases);
    struct model_case mirror = {"mirror", material_of(MATERIAL_MIRROR, vec3(0.9, 0.8, 0.7)), 1};
    struct model_case glass = {"glass", material_of(MATERIAL_GLASS, vec3_zero()), 1};
    glass.m.ior = 1.5;
    cases[n++] = mirror;
    cases[n++] = glass;
    cases[n++] = schlick_case("schlick r=0", vec3(0.5, 0.5, 0.5), 0.0, 1.0);
    return n;
}

/* Samples, evaluations and the albedo of m at wo are all finite (see below). */
static void check_finite_at(struct check *t, const struct material *m,
                            const struct shading_frame *f, struct vec3 wo, uint64_t key)
{
    struct rng rng = rng_stream(SEED, STREAM_TEST, key, 0);
    for (int i = 0; i < 1000; i++) {
        struct brdf_sample s;
        double u0 = rng_uniform(&rng), u1 = rng_uniform(&rng);
        if (!sample_with(m, f, wo, u0, u1, rng_uniform(&rng), &s))
            continue;
        CHECK(t, vec3_is_finite(s.weight) && isfinite(s.pdf) && s.pdf > 0);
        CHECK(t, fabs(vec3_length(s.wi) - 1) < 1e-12);
    }
    struct vec3 wis[3];
    wis[0] = f->n;
    wis[1] = vec3_sub(vec3_scale(f->n, 2 * vec3_dot(wo, f->n)), wo); /* the exact mirror */
    wis[2] = frame_direction(f, 1e-12, 2.0);
    for (int k = 0; k < 3; k++) {
        struct vec3 fr = brdf_eval(m, f, wo, wis[k]);
        double pdf = brdf_pdf(m, f, wo, wis[k]);
        CHECK(t, vec3_is_finite(fr) && vec3_max_component(vec3_neg(fr)) <= 0);
        CHECK(t, isfinite(pdf) && pdf >= 0);
    }
    struct vec3 albedo = brdf_albedo(m, f, wo);
    CHECK(t, vec3_is_finite(albedo) && vec3_max_component(albedo) <= 1);
}

/* truth: no NaN or Inf ever: at wo exactly along n, at cos_o = 1e-12, 1e-90 and 1e-300,
 *   on both sides of glass, every model's samples (1000 each) have finite weights, pdf > 0
 *   and unit wi; eval, pdf and albedo are finite and non-negative for wi along n,
 *   grazing, and wo's exact mirror (where Ward's lobe peaks as 1 / cos^2).
 * catches: 0 / 0 in a half vector at grazing, |wo + wi|^2 underflowing, exp() of huge
 *   arguments times huge normalisations, a lobe frame built from a zero vector. */
static void test_brdf_extreme_directions_stay_finite(struct check *t)
{
    static const double cos_o[] = {1.0, 1e-12, 1e-90, 1e-300};
    struct model_case cases[MAX_CASES];
    int n_cases = all_cases(cases);
    for (int c = 0; c < n_cases; c++) {
        for (int k = 0; k < 8; k++) {
            struct shading_frame f = shading_frame_from_normal(vec3(0, 0, 1), k % 2,
                                                               TRANSPORT_RADIANCE);
            struct vec3 wo = frame_direction(&f, cos_o[k / 2], 0.9);
            check_finite_at(t, &cases[c].m, &f, wo, 4000 + (uint64_t)(c * 8 + k));
        }
    }
}

/* truth: the conventions of brdf.h: reflection models give f = 0 and pdf = 0 for wi
 *   below the surface and refuse to sample when wo is below it; only mirror, glass and
 *   Schlick with r = 0 are all delta (pdf 0 everywhere), and they alone hold no photons.
 * catches: |cos| used where the sign matters (surfaces would transmit), a renderer
 *   storing photons on mirrors. */
static void test_brdf_below_surface_and_kinds(struct check *t)
{
    struct model_case cases[MAX_CASES];
    int n_cases = all_cases(cases);
    struct shading_frame f = test_frame(TRANSPORT_RADIANCE);
    struct vec3 wo = frame_direction(&f, 0.6, 0.2), below = frame_direction(&f, -0.3, 1.0);
    for (int c = 0; c < n_cases; c++) {
        const struct material *m = &cases[c].m;
        struct brdf_sample s;
        CHECK(t, vec3_max_abs(brdf_eval(m, &f, wo, below)) == 0);
        CHECK(t, brdf_pdf(m, &f, wo, below) == 0);
        CHECK(t, !sample_with(m, &f, below, 0.5, 0.5, 0.5, &s));
        int delta = m->kind == MATERIAL_MIRROR || m->kind == MATERIAL_GLASS ||
                    (m->kind == MATERIAL_SCHLICK && m->roughness == 0);
        CHECK(t, brdf_is_delta(m) == delta && brdf_has_diffuse(m) == !delta);
        CHECK(t, !delta || brdf_pdf(m, &f, wo, frame_direction(&f, 0.6, 0.2 + PI)) == 0);
    }
}

/* truth: f_r,d + f_r,s = f_r (Jensen 1996, Eq. 2) for every model, direction by
 * direction; the delta lobes all go to the specular part; a Lambertian diffuse part is
 * the constant rho / pi. */
static void test_brdf_split_sums_to_whole(struct check *t)
{
    struct model_case cases[MAX_CASES + 3];
    int n_cases = all_cases(cases);
    struct shading_frame f = test_frame(TRANSPORT_RADIANCE);
    struct rng rng = rng_stream(SEED, STREAM_TEST, 1001, 0);
    for (int c = 0; c < n_cases; c++) {
        const struct material *m = &cases[c].m;
        struct brdf_split split = brdf_split(m);
        int diffuse = m->kind == MATERIAL_SCHLICK ? m->roughness >= 0.5
                      : m->kind == MATERIAL_MIRROR || m->kind == MATERIAL_GLASS
                          ? 0
                          : vec3_max_component(m->rho) > 0;
        CHECK(t, split.has_diffuse == diffuse);
        CHECK(t, brdf_has_delta(m) ? split.has_specular && brdf_has_delta(&split.specular)
                                   : !split.has_diffuse || !brdf_has_delta(&split.diffuse));
        for (int i = 0; i < 500; i++) {
            double c1 = 1.0 - rng_uniform(&rng), c2 = 1.0 - rng_uniform(&rng);
            struct vec3 wo = frame_direction(&f, c1, 2 * PI * rng_uniform(&rng));
            struct vec3 wi = frame_direction(&f, c2, 2 * PI * rng_uniform(&rng));
            struct vec3 whole = brdf_eval(m, &f, wo, wi);
            struct vec3 d = split.has_diffuse ? brdf_eval(&split.diffuse, &f, wo, wi) : vec3_zero();
            struct vec3 sp = split.has_specular ? brdf_eval(&split.specular, &f, wo, wi)
                                                : vec3_zero();
            CHECK(t, close_vec3(vec3_add(d, sp), whole, 1e-12));
            if (split.has_diffuse && split.lambertian)
                CHECK(t, close_vec3(d, vec3_scale(split.diffuse.rho, 1.0 / PI), 1e-15));
        }
    }
    struct material phong = phong_case("phong", vec3(0.5, 0.3, 0.2), vec3(0.4, 0.4, 0.4), 10).m;
    struct brdf_split split = brdf_split(&phong);
    CHECK(t, split.has_diffuse && split.has_specular && split.lambertian);
    struct brdf_split sand = brdf_split(&cases[9].m); /* schlick r = 0.6: all diffuse */
    CHECK(t, sand.has_diffuse && !sand.has_specular && !sand.lambertian);
}

void test_brdf(struct check *t)
{
    RUN_TEST(t, test_brdf_pdf_matches_samples);
    RUN_TEST(t, test_brdf_reciprocity);
    RUN_TEST(t, test_brdf_albedo_at_most_one);
    RUN_TEST(t, test_brdf_white_furnace);
    RUN_TEST(t, test_brdf_glass_optics);
    RUN_TEST(t, test_coloured_glass);
    RUN_TEST(t, test_brdf_delta_lobes);
    RUN_TEST(t, test_brdf_extreme_directions_stay_finite);
    RUN_TEST(t, test_brdf_below_surface_and_kinds);
    RUN_TEST(t, test_brdf_split_sums_to_whole);
}
