/*
 * scene/brdf.c -- the material interface (brdf.h): local frames, dispatch, and the
 * models with no parameters beyond a reflectance: Lambert, the ideal mirror and glass.
 *
 * Every call turns world directions into the frame's local coordinates (z along n) and
 * hands them to a model; phong.c, ward.c and schlick.c hold the glossy ones
 * (brdf_models.h). A non-delta sample's weight and pdf are computed here from the
 * model's own eval and pdf, so the three always agree.
 *
 * Glass: eta = n_t / n_i with the outside at index 1; the reflected or refracted lobe is
 * chosen with the exact Fresnel probability F (optics.h), so its weight is the lobe's
 * reflectance over its probability: 1 for reflection, (1 - F) / (1 - F) / eta^2 for
 * radiance refracted (Veach 1997, Sec. 5.2).
 */
#include "brdf.h"

#include <assert.h>
#include <float.h>

#include "brdf_models.h"
#include "optics.h"

struct shading_frame shading_frame_from_normal(struct vec3 n, int front,
                                               enum transport transport)
{
    struct shading_frame f;
    f.n = n;
    vec3_frame(n, &f.t, &f.b);
    f.front = front;
    f.transport = transport;
    return f;
}

double shading_share(const struct shading_frame *f, struct vec3 ng, struct vec3 w)
{
    double geometric = fabs(vec3_dot(w, ng));
    return geometric > 0 ? fabs(vec3_dot(w, f->n)) / geometric : 0.0;
}

static struct vec3 to_local(const struct shading_frame *f, struct vec3 w)
{
    return vec3(vec3_dot(w, f->t), vec3_dot(w, f->b), vec3_dot(w, f->n));
}

static struct vec3 to_world(const struct shading_frame *f, struct vec3 w)
{
    return vec3_add(vec3_add(vec3_scale(f->t, w.x), vec3_scale(f->b, w.y)),
                    vec3_scale(f->n, w.z));
}

struct vec3 brdf_eval(const struct material *m, const struct shading_frame *f, struct vec3 wo,
                      struct vec3 wi)
{
    struct vec3 lo = to_local(f, wo), li = to_local(f, wi);
    if (!(lo.z > 0 && li.z > 0))
        return vec3_zero();
    switch (m->kind) {
    case MATERIAL_LAMBERT:
        return vec3_scale(m->rho, 1.0 / PI);
    case MATERIAL_PHONG:
        return phong_eval(m, lo, li);
    case MATERIAL_WARD:
        return ward_eval(m, lo, li);
    case MATERIAL_SCHLICK:
        return schlick_eval(m, lo, li);
    case MATERIAL_MIRROR:
    case MATERIAL_GLASS:
        break;
    }
    return vec3_zero();
}

static double pdf_local(const struct material *m, struct vec3 lo, struct vec3 li)
{
    switch (m->kind) {
    case MATERIAL_LAMBERT:
        return li.z / PI;
    case MATERIAL_PHONG:
        return phong_pdf(m, lo, li);
    case MATERIAL_WARD:
        return ward_pdf(m, lo, li);
    case MATERIAL_SCHLICK:
        return schlick_pdf(m, lo, li);
    case MATERIAL_MIRROR:
    case MATERIAL_GLASS:
        break;
    }
    return 0.0;
}

double brdf_pdf(const struct material *m, const struct shading_frame *f, struct vec3 wo,
                struct vec3 wi)
{
    struct vec3 lo = to_local(f, wo), li = to_local(f, wi);
    if (!(lo.z > 0 && li.z > 0))
        return 0.0;
    /* A glossy lobe's density grows as 1 / (wo . h); with wo within 1e-300 of the plane
     * and a lobe narrower than 1e-8 it would overflow: saturate instead of giving inf. */
    return fmin(pdf_local(m, lo, li), DBL_MAX);
}

/* The colour a refraction through glass lets pass: 1 - absorption per channel. */
static struct vec3 glass_filter(const struct material *m)
{
    return vec3_sub(vec3(1.0, 1.0, 1.0), m->absorption);
}

/* Glass's relative index n_t / n_i for light leaving towards wo (outside at index 1). */
static double glass_eta(const struct material *m, const struct shading_frame *f)
{
    assert(m->ior > 0);
    return f->front ? m->ior : 1.0 / m->ior;
}

/* One of glass's two delta lobes, chosen with the Fresnel probability. */
static int sample_glass(const struct material *m, const struct shading_frame *f,
                        struct vec3 wo, double u, struct brdf_sample *s)
{
    double eta = glass_eta(m, f);
    double reflectance = fresnel_dielectric(vec3_dot(wo, f->n), eta); /* 1 on TIR */
    s->delta = 1;
    if (u >= reflectance && refract(wo, f->n, eta, &s->wi)) {
        double scale = f->transport == TRANSPORT_RADIANCE ? 1.0 / (eta * eta) : 1.0;
        s->weight = vec3_scale(glass_filter(m), scale);
        s->pdf = 1.0 - reflectance; /* > 0: u < 1 and u >= reflectance */
        s->transmitted = 1;
        return 1;
    }
    s->wi = reflect(wo, f->n);
    s->weight = vec3(1.0, 1.0, 1.0);
    s->pdf = reflectance;
    return 1;
}

/* The lobe direction from the model; delta lobes come back complete. */
static int sample_local(const struct material *m, struct vec3 lo, const double u[3],
                        struct brdf_sample *s)
{
    switch (m->kind) {
    case MATERIAL_LAMBERT:
        assert(is_reflectance(m->rho));
        s->wi = sample_cosine_local(u[1], u[2]);
        return channel_mean(m->rho) > 0;
    case MATERIAL_MIRROR:
        assert(is_reflectance(m->rho));
        if (!(channel_mean(m->rho) > 0))
            return 0;
        s->wi = vec3(-lo.x, -lo.y, lo.z);
        s->weight = m->rho;
        s->pdf = 1.0;
        s->delta = 1;
        return 1;
    case MATERIAL_PHONG:
        return phong_sample(m, lo, u, s);
    case MATERIAL_WARD:
        return ward_sample(m, lo, u, s);
    case MATERIAL_SCHLICK:
        return schlick_sample(m, lo, u, s);
    case MATERIAL_GLASS:
        break;
    }
    return 0;
}

int brdf_sample(const struct material *m, const struct shading_frame *f, struct vec3 wo,
                const double u[3], struct brdf_sample *s)
{
    struct vec3 lo = to_local(f, wo);
    s->delta = 0;
    s->transmitted = 0;
    if (!(lo.z > 0))
        return 0;
    if (m->kind == MATERIAL_GLASS)
        return sample_glass(m, f, wo, u[0], s);
    if (!sample_local(m, lo, u, s) || !(s->wi.z > 0))
        return 0;
    struct vec3 li = s->wi;
    s->wi = to_world(f, li);
    if (s->delta)
        return 1;
    s->pdf = brdf_pdf(m, f, wo, s->wi);
    if (!(s->pdf > 0))
        return 0; /* a direction the pdf cannot see (underflow far out in a lobe's tail) */
    if (m->kind == MATERIAL_LAMBERT)
        s->weight = m->rho; /* (rho / pi) cos / (cos / pi), without rounding */
    else
        s->weight = vec3_scale(brdf_eval(m, f, wo, s->wi), vec3_dot(s->wi, f->n) / s->pdf);
    return 1;
}

int brdf_delta_lobes(const struct material *m, const struct shading_frame *f, struct vec3 wo,
                     struct brdf_sample lobes[2])
{
    assert(brdf_is_delta(m));
    /* u[0] = 0 picks the first lobe and the largest double below 1 the last (glass:
     * reflection below the Fresnel reflectance, refraction above), so both lobes come
     * from brdf_sample() itself; they coincide for the mirror and under total internal
     * reflection. */
    const double first[3] = {0.0, 0.0, 0.0}, last[3] = {1.0 - DBL_EPSILON / 2, 0.0, 0.0};
    int n = brdf_sample(m, f, wo, first, &lobes[0]);
    if (brdf_sample(m, f, wo, last, &lobes[n]) &&
        (n == 0 || lobes[1].transmitted != lobes[0].transmitted))
        n++;
    for (int i = 0; i < n; i++) {
        lobes[i].weight = vec3_scale(lobes[i].weight, lobes[i].pdf);
        lobes[i].pdf = 1.0;
    }
    return n;
}

struct vec3 brdf_albedo(const struct material *m, const struct shading_frame *f,
                        struct vec3 wo)
{
    struct vec3 lo = to_local(f, wo);
    if (!(lo.z > 0))
        return vec3_zero();
    switch (m->kind) {
    case MATERIAL_LAMBERT:
    case MATERIAL_MIRROR:
        return m->rho;
    case MATERIAL_GLASS: {
        /* F + (1 - F) T, written as 1 - (1 - F)(1 - T) so that clear glass gives exactly 1. */
        double reflectance = fresnel_dielectric(lo.z, glass_eta(m, f));
        return vec3_sub(vec3(1.0, 1.0, 1.0), vec3_scale(m->absorption, 1.0 - reflectance));
    }
    case MATERIAL_PHONG:
        return phong_albedo(m, lo);
    case MATERIAL_WARD:
        /* The bound: the specular albedo is at most rho_s (ward.c). */
        return vec3_add(m->rho, m->rho_s);
    case MATERIAL_SCHLICK:
        /* The bound: a + b + c = 1 and the glossy term's albedo is at most 1 (schlick.c);
         * exact for r = 0 and r = 1, which have no glossy term. */
        return m->rho;
    }
    return vec3_zero();
}

int brdf_is_delta(const struct material *m)
{
    return material_is_specular(m);
}

int brdf_has_non_delta(const struct material *m)
{
    return !material_is_specular(m);
}

int brdf_has_delta(const struct material *m)
{
    return m->kind == MATERIAL_MIRROR || m->kind == MATERIAL_GLASS ||
           (m->kind == MATERIAL_SCHLICK && m->roughness < 0.5); /* Schlick's c > 0 (schlick.c) */
}

/* m's Lambertian term rho / pi as a material of its own. */
static struct material lambertian_part(const struct material *m, struct vec3 rho)
{
    struct material part = *m;
    part.kind = MATERIAL_LAMBERT;
    part.rho = rho;
    part.emission = vec3_zero();
    return part;
}

/* m without its Lambertian term (phong and ward: the glossy lobe alone). */
static struct material without_lambertian(const struct material *m)
{
    struct material part = *m;
    part.rho = vec3_zero();
    part.emission = vec3_zero();
    return part;
}

struct brdf_split brdf_split(const struct material *m)
{
    struct brdf_split s;
    s.diffuse = lambertian_part(m, vec3_zero());
    s.specular = without_lambertian(m);
    s.lambertian = 1;
    switch (m->kind) {
    case MATERIAL_LAMBERT:
        s.diffuse = lambertian_part(m, m->rho);
        break;
    case MATERIAL_MIRROR:
    case MATERIAL_GLASS:
        s.specular = *m;
        s.specular.emission = vec3_zero();
        break;
    case MATERIAL_PHONG:
    case MATERIAL_WARD:
        s.diffuse = lambertian_part(m, m->rho);
        break;
    case MATERIAL_SCHLICK:
        if (m->roughness >= 0.5) {
            s.diffuse = *m;
            s.diffuse.emission = vec3_zero();
            s.lambertian = m->roughness == 1; /* no glossy term: b = 4 r (1 - r) = 0 */
            s.specular = lambertian_part(m, vec3_zero());
        } else {
            s.specular = *m;
            s.specular.emission = vec3_zero();
        }
        break;
    }
    s.has_diffuse = channel_mean(s.diffuse.rho) > 0;
    s.has_specular = m->kind == MATERIAL_GLASS ||
                     (s.specular.kind == MATERIAL_PHONG || s.specular.kind == MATERIAL_WARD
                          ? channel_mean(s.specular.rho_s) > 0
                          : channel_mean(s.specular.rho) > 0);
    return s;
}
