/*
 * tests/test_trace.c -- photon tracing (photon/trace.c): the flux kept through bounces and
 * Russian roulette, the path classes (direct, caustic, indirect, shadow photons; glossy
 * caustics when each bounce chooses a part of the BRDF),
 * determinism, and the limits on what is stored, against closed forms and against each
 * other. Emission is test_trace_emission.c's; what is made of the photons,
 * test_trace_estimates.c's and test_trace_photons_mode.c's.
 *
 * Statistical checks use fixed seeds and standard errors estimated from the same
 * photons. Photon powers after Russian roulette are not identically distributed
 * photon by photon, but the paths are independent and identically distributed: a path's
 * contribution (the sum of the powers it stored) is the unit whose variance is
 * estimated. Where a path can store at most one photon of the class summed (first hits,
 * caustics ending a caustic map's path), the stored photons in path order are those
 * contributions; elsewhere each path is traced alone (n_emit = 1, pass = path index).
 */
#include <math.h>
#include <string.h>

#include "../src/photon/trace.h"
#include "check.h"
#include "files.h"
#include "tests.h"
#include "trace_fixtures.h"
#include "truths.h"

/* ---- tracing ---- */

/* Per-channel totals of n paths traced one at a time (photon i alone, pass i), each
 * path's stored power summed: the iid contributions. first: the same for first hits;
 * *direct_exact: whether every path stored exactly one direct photon of power Phi. */
static void trace_paths(const struct scene *scene, size_t n, struct tally total[3],
                        struct tally first[3], int *direct_exact)
{
    struct vec3 phi = light_power(&scene->lights[0]);
    *direct_exact = 1;
    for (int a = 0; a < 3; a++) {
        total[a].sum = total[a].sum2 = first[a].sum = first[a].sum2 = 0;
        total[a].n = first[a].n = (double)n;
    }
    for (size_t i = 0; i < n; i++) {
        struct photon_trace tr = trace(scene, 1, PHOTON_MAP_GLOBAL, i, NULL);
        struct vec3 path = vec3_zero(), direct = vec3_zero();
        for (size_t p = 0; p < tr.n_photons; p++) {
            struct vec3 power = photon_power(&tr.photons[p]);
            path = vec3_add(path, power);
            if (tr.photons[p].flags & PHOTON_DIRECT)
                direct = vec3_add(direct, power);
        }
        *direct_exact &= tr.n_direct == 1 && vec3_length2(vec3_sub(direct, phi)) == 0;
        for (int a = 0; a < 3; a++) {
            tally_add(&total[a], vec3_get(path, a));
            tally_add(&first[a], vec3_get(direct, a));
        }
        photon_trace_free(&tr);
    }
}

/* truth: scenes/analytic/closed-box.scene, a point light of Phi = 1 W inside a closed
 *   Lambertian box: the flux stored at first hits is Phi, and over all bounces
 *   Phi (1 + rho + rho^2 + ...) = Phi / (1 - rho), per channel. Grey rho = 0.5 (total
 *   2 W); then the walls recoloured to rho = (0.8, 0.4, 0.2) (totals 5, 5/3, 5/4 W).
 * tolerance: first hits exactly Phi (1 W is exact in the record and a grey first hit
 *   has had no roulette); totals within 3 standard errors of 20000 independent paths,
 *   plus the record's rounding for the coloured box (a power that has taken the walls'
 *   colour is no longer exact: at most the largest channel / 255.5 per stored photon).
 * catches: roulette without dividing by q (the grey total would be 4/3), storing after
 *   instead of before the roulette (total 1 instead of 2), photons lost through the
 *   box's seams, first hits not classed as direct, a depth limit cutting paths, a
 *   channel scaled by another's albedo. (Any q in (0, 1] keeps the sums unbiased, so
 *   the choice of q is not what this tests.) */
static void test_closed_box_flux(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/closed-box.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    CHECK(t, scene->n_lights == 1 && scene->n_materials == 1);
    struct tally total[3], first[3];
    int direct_exact = 0;
    trace_paths(scene, 20000, total, first, &direct_exact);
    CHECK(t, direct_exact);
    for (int a = 0; a < 3; a++) {
        CHECK(t, first[a].sum == 20000);
        CHECK_CLOSE(t, total[a].sum / 20000, 2.0, 3 * tally_se(&total[a]) / 20000);
    }
    scene->materials[0].rho = vec3(0.8, 0.4, 0.2);
    trace_paths(scene, 20000, total, first, &direct_exact);
    CHECK(t, direct_exact);
    double rounding = total[0].sum * RGBE_REL; /* channel 0 is the largest throughout */
    for (int a = 0; a < 3; a++) {
        double rho = vec3_get(scene->materials[0].rho, a);
        CHECK_CLOSE(t, total[a].sum / 20000, 1 / (1 - rho),
                    (3 * tally_se(&total[a]) + rounding) / 20000);
    }
    scene_free(scene);
}

/* A point light of 1000 W at (0, 1, 0) over a 200 x 200 Lambertian floor (rho = 0.5)
 * and, if `mirror`, a 1 x 1 mirror of reflectance 0.8 at height 2 facing down. */
static struct scene *mirror_scene(int mirror)
{
    struct scene *scene = scene_create();
    int floor = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    int chrome = add_test_material(scene, MATERIAL_MIRROR, vec3(0.8, 0.8, 0.8), vec3_zero());
    add_square(scene, vec3(0, 0, 0), 100, 1, floor);
    if (mirror)
        add_square(scene, vec3(0, 2, 0), 0.5, 0, chrome);
    scene_add_point_light(scene, vec3(0, 1, 0), vec3(1000, 1000, 1000));
    finish_test_scene(scene);
    return scene;
}

/* truth: a mirror in front of a wall makes a caustic; without it there is none. The
 *   point light sees the 1 x 1 mirror at distance 1 in the solid angle
 *   Omega = 4 asin(a b / sqrt((a^2 + 4 d^2)(b^2 + 4 d^2))) = 4 asin(1/5) (a rectangle
 *   seen from its axis), so the caustic flux is rho_m Phi Omega / (4 pi), and it lands
 *   where the image source (0, 3, 0) sees the mirror: |x|, |z| <= 1.5.
 * tolerance: the flux within 3 binomial standard errors (100000 photons, about 5000 of
 *   them caustic) plus the record's rounding; the footprint to 1e-6.
 * catches: mirror bounces counted as diffuse (the caustic classed indirect), a caustic
 *   map storing the first (direct) hit, roulette at a mirror not divided by q, classes
 *   leaking into a scene without specular surfaces. */
static void test_mirror_caustic_classes(struct check *t)
{
    size_t n = 100000;
    struct scene *plain = mirror_scene(0);
    struct photon_trace tr = trace(plain, n, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_direct > 0 && tr.n_caustic == 0 && tr.n_indirect == 0);
    photon_trace_free(&tr);
    scene_free(plain);
    struct scene *scene = mirror_scene(1);
    tr = trace(scene, n, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_caustic > 0 && tr.n_indirect > 0 && tr.n_shadow == 0);
    struct tally f = {0, 0, (double)n};
    for (size_t i = 0; i < tr.n_photons; i++) {
        if (!(tr.photons[i].flags & PHOTON_CAUSTIC))
            continue;
        struct vec3 x = photon_position(&tr.photons[i]);
        CHECK(t, fabs(x.y) < 1e-6 && fabs(x.x) <= 1.5 + 1e-6 && fabs(x.z) <= 1.5 + 1e-6);
        tally_add(&f, photon_power(&tr.photons[i]).y);
    }
    double expected = 0.8 * 1000 * 4 * asin(0.2) / (4 * PI);
    CHECK_CLOSE(t, f.sum, expected, 3 * tally_se(&f) + expected * RGBE_REL);
    photon_trace_free(&tr);
    tr = trace(scene, n, PHOTON_MAP_CAUSTIC, 0, NULL);
    CHECK(t, tr.n_photons == tr.n_caustic && tr.n_direct == 0 && tr.n_indirect == 0);
    photon_trace_free(&tr);
    scene_free(scene);
}

/* The flux a light of 1000 W at (0, 1, 0) throws onto a Lambertian floor (rho = 0.5) after
 * exactly one bounce off a 1 x 1 panel of Ward's model at height 2 facing down
 * (rho_d, rho_s, alpha 0.1), traced with max_depth 1 and by_parts as given; per class
 * (caustic, indirect), as tallies of the n paths (each stores at most one such photon). */
static void panel_flux(struct check *t, double rho_d, double rho_s, int by_parts, size_t n,
                       struct tally *caustic, struct tally *indirect)
{
    char path[256], text[512];
    temp_name(path, sizeof path, "trace", "panel.scene");
    sprintf(text, "camera 0 1 -5 0 1 0 0 1 0 40\n"
                  "material floor lambert 0.5 0.5 0.5\n"
                  "material panel ward %g %g %g %g %g %g 0.1 0.1\n"
                  "quad -100 0 -100 -100 0 100 100 0 100 100 0 -100 floor\n"
                  "quad -0.5 2 -0.5 0.5 2 -0.5 0.5 2 0.5 -0.5 2 0.5 panel\n"
                  "light point 0 1 0 1000 1000 1000\n",
            rho_d, rho_d, rho_d, rho_s, rho_s, rho_s);
    write_text_file(path, text);
    struct scene *scene = load_test_scene(path, 8, 8);
    remove(path);
    CHECK(t, scene != NULL);
    caustic->sum = caustic->sum2 = indirect->sum = indirect->sum2 = 0;
    caustic->n = indirect->n = (double)n;
    if (scene == NULL)
        return;
    struct trace_settings ts = {SEED, 0, n, MAX_PHOTONS, PHOTON_MAP_GLOBAL, 1, NULL, NULL,
                                by_parts, NULL};
    struct photon_trace tr;
    struct error err;
    CHECK(t, trace_photons(scene, &ts, &tr, &err) == 0);
    for (size_t i = 0; i < tr.n_photons; i++) {
        if (!(fabs(photon_position(&tr.photons[i]).y) < 1e-6) ||
            (tr.photons[i].flags & PHOTON_DIRECT))
            continue; /* on the panel, or a first hit */
        double power = photon_power(&tr.photons[i]).y;
        tally_add((tr.photons[i].flags & PHOTON_CAUSTIC) ? caustic : indirect, power);
    }
    photon_trace_free(&tr);
    scene_free(scene);
}

/* truth: Jensen 1996, Eq. 2: f_r = f_r,d + f_r,s, and a caustic is light reflected by
 *   f_r,s, glossy lobes included. With by_parts each bounce leaves through one part, so
 *   the light a panel of both parts (rho_d 0.3, rho_s 0.5) throws onto the floor splits
 *   into a caustic equal to what a panel of the specular part alone (rho_d 0) throws and
 *   an indirect part equal to a Lambertian panel's (rho_s 0), each traced without
 *   by_parts, where a glossy bounce is never a caustic: the three traces share no
 *   photon. Together the two classes equal the whole panel's flux without by_parts.
 * tolerance: 3 combined standard errors of 200000 paths each, plus the record's
 *   rounding.
 * catches: a part's sample not divided by the probability of choosing it (the indirect
 *   part 2.7 times too dark here), the classes swapped or a glossy bounce classed as
 *   diffuse (no caustic), the split losing or doubling light, by_parts leaking into the
 *   default. */
static void test_glossy_caustics_by_parts(struct check *t)
{
    const size_t n = 200000;
    struct tally c, d, c_s, d_s, c_d, d_d, c_0, d_0;
    panel_flux(t, 0.3, 0.5, 1, n, &c, &d);
    panel_flux(t, 0.0, 0.5, 0, n, &c_s, &d_s);
    panel_flux(t, 0.3, 0.0, 0, n, &c_d, &d_d);
    panel_flux(t, 0.3, 0.5, 0, n, &c_0, &d_0);
    CHECK(t, c.sum > 0 && d.sum > 0);
    CHECK(t, c_s.sum == 0 && c_d.sum == 0 && c_0.sum == 0); /* no delta lobe: no caustic */
    double se_c = sqrt(pow(tally_se(&c), 2) + pow(tally_se(&d_s), 2));
    double se_d = sqrt(pow(tally_se(&d), 2) + pow(tally_se(&d_d), 2));
    double se_0 = sqrt(pow(tally_se(&c), 2) + pow(tally_se(&d), 2) + pow(tally_se(&d_0), 2));
    CHECK_CLOSE(t, c.sum, d_s.sum, 3 * se_c + (c.sum + d_s.sum) * RGBE_REL);
    CHECK_CLOSE(t, d.sum, d_d.sum, 3 * se_d + (d.sum + d_d.sum) * RGBE_REL);
    CHECK_CLOSE(t, c.sum + d.sum, d_0.sum, 3 * se_0 + (c.sum + d.sum + d_0.sum) * RGBE_REL);
}

/* truth: Jensen and Christensen 1995: a light ray followed through the occluder (a
 *   0.5 x 0.5 square at height 1 under a point light at height 2) stores one shadow
 *   photon on the floor behind it, so there are exactly as many shadow photons as
 *   direct photons on the occluder; all of them lie in the occluder's shadow
 *   (|x|, |z| <= 0.5), no direct floor photon does, and each carries zero power and the
 *   direction back towards the light. Without the option there are none.
 * tolerance: positions to 1e-6 (floats of values near 1); directions to the record's
 *   1.06 degrees.
 * catches: shadow photons stored at the first hit, or with power (they would brighten
 *   estimates), the continued ray re-hitting the occluder, direct photons leaking into
 *   the shadow, the direction pointing away from the light. */
static void test_shadow_photons(struct check *t)
{
    struct scene *scene = scene_create();
    int grey = add_test_material(scene, MATERIAL_LAMBERT, vec3(0.5, 0.5, 0.5), vec3_zero());
    add_square(scene, vec3(0, 0, 0), 100, 1, grey);
    add_square(scene, vec3(0, 1, 0), 0.25, 1, grey);
    struct vec3 light = vec3(0, 2, 0);
    scene_add_point_light(scene, light, vec3(10, 10, 10));
    finish_test_scene(scene);
    struct photon_trace tr = trace(scene, 50000, PHOTON_MAP_GLOBAL | PHOTON_SHADOW, 0, NULL);
    size_t on_occluder = 0;
    CHECK(t, tr.n_shadow > 100);
    for (size_t i = 0; i < tr.n_photons; i++) {
        const struct photon *p = &tr.photons[i];
        struct vec3 x = photon_position(p);
        int in_shadow = fabs(x.x) <= 0.5 + 1e-6 && fabs(x.z) <= 0.5 + 1e-6;
        int on_floor = fabs(x.y) < 1e-6;
        on_occluder += (p->flags & PHOTON_DIRECT) && !on_floor;
        if (p->flags & PHOTON_DIRECT)
            CHECK(t, !(on_floor && fabs(x.x) < 0.5 - 1e-6 && fabs(x.z) < 0.5 - 1e-6));
        if (!(p->flags & PHOTON_SHADOW))
            continue;
        struct vec3 to_light = vec3_normalize(vec3_sub(light, x));
        CHECK(t, on_floor && in_shadow && vec3_length2(photon_power(p)) == 0);
        CHECK(t, vec3_dot(photon_direction(p), to_light) >= cos(PI / 510 + PI / 256));
    }
    CHECK(t, on_occluder == tr.n_shadow);
    photon_trace_free(&tr);
    tr = trace(scene, 10000, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_shadow == 0);
    photon_trace_free(&tr);
    scene_free(scene);
}

/* truth: none; both sides are the same computation. Photon i's path depends only on its
 *   stream, so the same seed gives the same bytes, and a trace of 2N photons begins with
 *   the N-photon trace's photons at the same places, each with exactly twice the power
 *   (Phi / N against Phi / (2N): doubling is exact in binary).
 * tolerance: none (bytes and exact doubles).
 * catches: random numbers shared between photons, state carried from one photon to the
 *   next, powers depending on anything but N. */
static void test_trace_determinism(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct photon_trace a = trace(scene, 2000, PHOTON_MAP_GLOBAL, 3, NULL);
    struct photon_trace b = trace(scene, 2000, PHOTON_MAP_GLOBAL, 3, NULL);
    struct photon_trace half = trace(scene, 1000, PHOTON_MAP_GLOBAL, 3, NULL);
    CHECK(t, a.n_photons == b.n_photons && a.n_photons > 2000);
    CHECK(t, memcmp(a.photons, b.photons, a.n_photons * sizeof *a.photons) == 0);
    CHECK(t, half.n_photons < a.n_photons);
    for (size_t i = 0; i < half.n_photons && i < a.n_photons; i++) {
        const struct photon *p = &half.photons[i], *q = &a.photons[i];
        CHECK(t, memcmp(p->pos, q->pos, sizeof p->pos) == 0 && p->flags == q->flags);
        CHECK(t, p->theta == q->theta && p->phi == q->phi);
        struct vec3 doubled = vec3_scale(photon_power(q), 2.0);
        CHECK(t, vec3_length2(vec3_sub(photon_power(p), doubled)) == 0);
    }
    photon_trace_free(&half);
    photon_trace_free(&b);
    photon_trace_free(&a);
    scene_free(scene);
}

/* truth: the contract: more stored photons than max_stored fail with a message and
 *   leave nothing allocated; exactly max_stored succeed.
 * tolerance: none.
 * catches: a map silently truncated (Jensen's store() drops photons when full), a
 *   failure that leaks the array. */
static void test_trace_refuses_overflow(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/closed-box.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct photon_trace full = trace(scene, 100, PHOTON_MAP_GLOBAL, 0, NULL);
    struct trace_settings ts = {SEED,         0,    100, 0, PHOTON_MAP_GLOBAL, TEST_MAX_DEPTH,
                                NULL,         NULL, 0,    NULL};
    struct photon_trace out;
    struct error err;
    ts.max_stored = full.n_photons;
    CHECK(t, trace_photons(scene, &ts, &out, &err) == 0 && out.n_photons == full.n_photons);
    photon_trace_free(&out);
    ts.max_stored = full.n_photons - 1;
    err.message[0] = '\0';
    CHECK(t, trace_photons(scene, &ts, &out, &err) == -1);
    CHECK(t, out.photons == NULL && out.n_photons == 0 && strstr(err.message, "more than"));
    photon_trace_free(&full);
    scene_free(scene);
}

/* truth: photon.h's contract: photon_pack() takes powers below PHOTON_POWER_MAX (2^127 W)
 *   only, and trace.c promises no photon outside that range is stored. A light's power is
 *   set past the scene's limit by hand here (the parser refuses it: test_scene.c), so
 *   that photons leave at just under 2^127 W and a Ward lobe of rho_s = 1 between two
 *   facing planes scatters them with weights up to 2, out of range.
 * tolerance: none.
 * catches: a photon whose power grew past the record's range packed (an assertion, or
 *   a wrapped exponent byte), a light of non-representable power emitting at all. */
static void test_trace_keeps_powers_in_range(struct check *t)
{
    char path[256];
    temp_name(path, sizeof path, "trace", "slab.scene");
    write_text_file(path, "camera 0 0.5 -5 0 0.5 0 0 1 0 40\n"
                          "material w ward 0 0 0 1 1 1 0.3 0.3\n"
                          "quad -50 0 -50 -50 0 50 50 0 50 50 0 -50 w\n"
                          "quad -50 1 -50 50 1 -50 50 1 50 -50 1 50 w\n"
                          "light point 0 0.5 0 1 1 1\n");
    struct scene *scene = load_test_scene(path, 8, 8);
    remove(path);
    CHECK(t, scene != NULL && scene->n_lights == 1);
    if (scene == NULL)
        return;
    const size_t n = 200;
    scene->lights[0].power = vec3_scale(vec3(1, 0.5, 0.25), 0.99 * PHOTON_POWER_MAX * n);
    struct photon_trace tr = trace(scene, n, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_photons > n); /* the first hits, and later ones that stayed in range */
    size_t lost = 0;
    for (size_t i = 0; i < tr.n_photons; i++) {
        struct vec3 power = photon_power(&tr.photons[i]);
        CHECK(t, vec3_is_finite(power) && vec3_max_component(power) <= PHOTON_POWER_MAX);
        lost += !(vec3_max_component(power) > 0);
    }
    CHECK(t, lost == 0);
    photon_trace_free(&tr);
    scene->lights[0].power = vec3(1e300, 1e300, 1e300);
    tr = trace(scene, n, PHOTON_MAP_GLOBAL, 0, NULL);
    CHECK(t, tr.n_photons == 0);
    photon_trace_free(&tr);
    scene_free(scene);
}

void test_trace(struct check *t)
{
    RUN_TEST(t, test_closed_box_flux);
    RUN_TEST(t, test_mirror_caustic_classes);
    RUN_TEST(t, test_glossy_caustics_by_parts);
    RUN_TEST(t, test_shadow_photons);
    RUN_TEST(t, test_trace_determinism);
    RUN_TEST(t, test_trace_refuses_overflow);
    RUN_TEST(t, test_trace_keeps_powers_in_range);
}
