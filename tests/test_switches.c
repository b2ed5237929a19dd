/*
 * tests/test_switches.c -- the switches that turn a departure of the photon map modes
 * (photons, 1994, 1996) back to the paper's side (src/modes/README.md names each): each
 * changes the image, in the direction the paper's way predicts where one can be told, and
 * only where its term of the rendering acts. Tiny renders of the Cornell boxes, through the binary as a user
 * runs it. The records' reach is also checked on its own, against values by hand
 * (test_cache.c does the same for the defaults).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/error.h"
#include "../src/image/image.h"
#include "../src/modes/cache_pass.h"
#include "files.h"
#include "tests.h"

#define OUT "build/test_switches"

/* Renders "--no-progress --stats WORDS -o OUT_name.pfm" (WORDS ending in the scene) with
 * its --stats in OUT_name.log; whether it exited 0. */
static int render(const char *words, const char *name)
{
    char args[1024], log[256];
    snprintf(args, sizeof args, "--no-progress --stats %s -o %s_%s.pfm", words, OUT, name);
    snprintf(log, sizeof log, "%s_%s.log", OUT, name);
    return photon_logged("", args, log) == 0;
}

/* The --stats number key of render name; -1 when it printed none. */
static double stat_of(const char *name, const char *key)
{
    char log[256];
    snprintf(log, sizeof log, "%s_%s.log", OUT, name);
    return file_stat(log, key);
}

/* Whether renders a and b wrote the same PFM bytes. */
static int same_image(const char *a, const char *b)
{
    char pa[256], pb[256];
    snprintf(pa, sizeof pa, "%s_%s.pfm", OUT, a);
    snprintf(pb, sizeof pb, "%s_%s.pfm", OUT, b);
    return files_equal(pa, pb);
}

/* The sum of every channel of every pixel of render name's PFM (or of the PFM file name
 * itself when it ends in .pfm); NAN when it cannot be read. */
static double image_sum(const char *name)
{
    char file[256];
    if (strstr(name, ".pfm") != NULL)
        snprintf(file, sizeof file, "%s", name);
    else
        snprintf(file, sizeof file, "%s_%s.pfm", OUT, name);
    struct error err;
    struct image *img = pfm_read(file, &err);
    if (img == NULL)
        return NAN;
    double sum = 0;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            struct vec3 v = image_get(img, x, y);
            sum += v.x + v.y + v.z;
        }
    image_free(img);
    return sum;
}

/* Removes what render() wrote for name. */
static void remove_render(const char *name)
{
    static const char *const endings[] = {".pfm", ".png", ".log"};
    for (size_t i = 0; i < sizeof endings / sizeof endings[0]; i++) {
        char file[256];
        snprintf(file, sizeof file, "%s_%s%s", OUT, name, endings[i]);
        remove(file);
    }
}

/* The small settings every render here shares, before the mode's own words. */
#define TINY_WORK "--spp 2 --specular-spp 2 --photons 20000 --gather-rays 16"
#define TINY "--width 24 --height 24 " TINY_WORK
#define TINY_1996 TINY " --caustic-photons 20000"
#define SPECULAR_BOX " scenes/cornell-specular.scene"
#define PLAIN_BOX " scenes/cornell.scene"

/* truth: --caustic-radius-fraction bounds only the caustic estimates (4.0.2 in 1994, 4.3
 *   in 1996): the Cornell box has no mirror or glass, so no caustic photon and the same
 *   bytes at any fraction; the specular box's caustics, of sparse photons away from the
 *   balls' bright spots, are read over a disc 16 times larger at 1 than at 0.25, which
 *   changes them.
 * catches: the option ignored by a mode, or applied to the global estimates too. */
static void test_caustic_radius_fraction(struct check *t)
{
    static const char *const modes[] = {"--mode 1994 " TINY, "--mode 1996 " TINY_1996};
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        char words[512];
        snprintf(words, sizeof words, "%s" PLAIN_BOX, modes[i]);
        CHECK(t, render(words, "plain_quarter"));
        snprintf(words, sizeof words, "%s --caustic-radius-fraction 1" PLAIN_BOX, modes[i]);
        CHECK(t, render(words, "plain_whole"));
        CHECK(t, same_image("plain_quarter", "plain_whole"));
        snprintf(words, sizeof words, "%s" SPECULAR_BOX, modes[i]);
        CHECK(t, render(words, "quarter"));
        snprintf(words, sizeof words, "%s --caustic-radius-fraction 1" SPECULAR_BOX, modes[i]);
        CHECK(t, render(words, "whole"));
        CHECK(t, !same_image("quarter", "whole"));
    }
    remove_render("plain_quarter");
    remove_render("plain_whole");
    remove_render("quarter");
    remove_render("whole");
}

/* truth: Jensen 1996, Sec. 5, and Jensen and Christensen 1994, Sec. 3.3: an estimate's
 *   sphere grows until it holds its photons, with no bound. Among 2,000 photons in the
 *   Cornell box an estimate's k photons lie farther than the default bound, a tenth of the
 *   diagonal (96 mm), so --no-max-radius changes every photon mode's image, and --stats
 *   reports no radius (inf); where k = 10 of 200,000 photons lie within a few millimetres
 *   the bound never acts: the same bytes. --paper has no bound: the same bytes as with
 *   --no-max-radius spelled out, not those of --paper with a bound.
 * catches: --no-max-radius ignored by a mode or read as the default (0 was the default
 *   before it), a bound that acts where it should not, --paper keeping the bound. */
#define SPARSE "--width 24 --height 24 --photons 2000"
static void test_max_radius(struct check *t)
{
    static const char *const modes[] = {
        "--mode photons " SPARSE,
        "--mode 1994 " SPARSE " --spp 2 --specular-spp 2 --gather-rays 16",
        "--mode 1996 " SPARSE " --spp 2 --specular-spp 2 --gather-rays 16 --caustic-photons 2000"};
    char words[512];
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        snprintf(words, sizeof words, "%s" PLAIN_BOX, modes[i]);
        CHECK(t, render(words, "bound"));
        snprintf(words, sizeof words, "%s --no-max-radius" PLAIN_BOX, modes[i]);
        CHECK(t, render(words, "unbound"));
        CHECK(t, !same_image("bound", "unbound"));
        snprintf(words, sizeof words, "%s --paper" PLAIN_BOX, modes[i]);
        CHECK(t, render(words, "paper"));
        snprintf(words, sizeof words, "%s --paper --no-max-radius" PLAIN_BOX, modes[i]);
        CHECK(t, render(words, "paper_unbound"));
        snprintf(words, sizeof words, "%s --paper --max-radius 96" PLAIN_BOX, modes[i]);
        CHECK(t, render(words, "paper_bound"));
        CHECK(t, same_image("paper", "paper_unbound") && !same_image("paper", "paper_bound"));
        if (i == 0) /* the photons mode reports its radius */
            CHECK(t, isinf(stat_of("unbound", "max_radius")) &&
                         fabs(stat_of("bound", "max_radius") - 96.074) < 0.001);
    }
    const char *dense = "--mode photons --width 24 --height 24 --photons 200000 --gather 10";
    snprintf(words, sizeof words, "%s" PLAIN_BOX, dense);
    CHECK(t, render(words, "bound"));
    snprintf(words, sizeof words, "%s --no-max-radius" PLAIN_BOX, dense);
    CHECK(t, render(words, "unbound"));
    CHECK(t, same_image("bound", "unbound"));
    remove_render("bound");
    remove_render("unbound");
    remove_render("paper");
    remove_render("paper_unbound");
    remove_render("paper_bound");
}

/* A glass ball (index 1.5) filling most of the view in front of a wall that emits 1 and
 * reflects nothing: a pixel through the ball is the Fresnel-weighted sum of what its two
 * lobes see, the emitter (refracted) and the black background (reflected), and nothing
 * else in the scene adds noise. */
static const char glass_scene[] =
    "image 16 16\n"
    "camera 0 0 0  0 0 1  0 1 0  30\n"
    "material glass glass 1.5\n"
    "sphere 0 0 5 1.5 glass\n"
    "light quad -6 -6 10  -6 6 10  6 6 10  6 -6 10  1 1 1\n";

/* truth: Monte Carlo: choosing one of a glass's two lobes by its Fresnel weight has the
 *   same mean as following both (the paper's 4.2 and 1994's L_r,s, estimators of the
 *   same integral), and adds the choice's variance, R (1 - R) of the refracted view's
 *   radiance squared at each bounce, which following both has not. Over the glass ball in
 *   front of an emitter, the image's summed variance of the mean is 30 times larger with
 *   --no-both-lobes at 16 samples (4.8 against 0.14-0.30).
 * tolerance: the means within 2% of the image's sum (the one-lobe sum's standard error
 *   is 0.3%); the variance at least 4 times larger.
 * catches: --no-both-lobes ignored, a lobe followed without dividing by its probability
 *   or the two lobes' weights added twice (both change the mean). */
static void test_both_lobes(struct check *t)
{
    static const char *const modes[] = {"--mode 1994", "--mode 1996"};
    write_text_file(OUT "_glass.scene", glass_scene);
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        char words[512];
        const char *common = "--spp 16 --specular-spp 16 --photons 1000 --gather-rays 16";
        snprintf(words, sizeof words, "%s %s --variance %s_vboth.pfm %s_glass.scene", modes[i],
                 common, OUT, OUT);
        CHECK(t, render(words, "both"));
        snprintf(words, sizeof words, "%s %s --no-both-lobes --variance %s_vone.pfm "
                 "%s_glass.scene", modes[i], common, OUT, OUT);
        CHECK(t, render(words, "one"));
        double both = image_sum("both"), one = image_sum("one");
        CHECK(t, both > 0 && fabs(one - both) < 0.02 * both);
        CHECK(t, image_sum(OUT "_vone.pfm") > 4 * image_sum(OUT "_vboth.pfm"));
    }
    remove_render("both");
    remove_render("one");
    remove(OUT "_vboth.pfm");
    remove(OUT "_vone.pfm");
    remove(OUT "_glass.scene");
}

/* truth: Jensen 1996, Sec. 4: "We use the accurate computation if the surface is seen
 *   directly by the eye or perhaps via a few specular reflections", the specular part
 *   including highly glossy lobes, and the accurate soft indirect light is a final gather
 *   (4.4). So with --no-glossy-corner the walls seen in the glossy floor of
 *   scenes/cornell-glossy.scene gather, where the corner way reads the global map: more
 *   gathers, and another image. The Cornell box has no glossy lobe: the same bytes.
 * catches: the switch ignored, or acting on surfaces not seen through a glossy lobe. */
static void test_glossy_corner(struct check *t)
{
    const char *common = "--mode 1996 " TINY " --caustic-photons 1000";
    char words[512];
    snprintf(words, sizeof words, "%s scenes/cornell-glossy.scene", common);
    CHECK(t, render(words, "corner"));
    snprintf(words, sizeof words, "%s --no-glossy-corner scenes/cornell-glossy.scene", common);
    CHECK(t, render(words, "accurate"));
    CHECK(t, stat_of("accurate", "gathers") > stat_of("corner", "gathers") &&
                 stat_of("corner", "gathers") > 0);
    CHECK(t, !same_image("corner", "accurate"));
    snprintf(words, sizeof words, "%s" PLAIN_BOX, common);
    CHECK(t, render(words, "plain_corner"));
    snprintf(words, sizeof words, "%s --no-glossy-corner" PLAIN_BOX, common);
    CHECK(t, render(words, "plain_accurate"));
    CHECK(t, same_image("plain_corner", "plain_accurate"));
    remove_render("corner");
    remove_render("accurate");
    remove_render("plain_corner");
    remove_render("plain_accurate");
}

/* truth: Jensen 1996, Sec. 4: the end of a gather ray shorter than "a small threshold" is
 *   evaluated accurately, and the accurate soft indirect light is a final gather (4.4).
 *   So with --no-corner-photons the corners of the Cornell box, where gather rays are
 *   short, gather where the default reads the global map's indirect photons: more
 *   gathers, and another image; with --accurate-distance 0 there is no corner, and the
 *   switch changes no byte. --paper gathers there too: more gathers than --paper with
 *   --corner-photons.
 * catches: the switch ignored, acting away from corners, or left out of --paper. */
static void test_corner_photons(struct check *t)
{
    const char *common = "--mode 1996 " TINY_1996;
    char words[512];
    snprintf(words, sizeof words, "%s" PLAIN_BOX, common);
    CHECK(t, render(words, "photons"));
    snprintf(words, sizeof words, "%s --no-corner-photons" PLAIN_BOX, common);
    CHECK(t, render(words, "gathered"));
    CHECK(t, stat_of("gathered", "gathers") > stat_of("photons", "gathers") &&
                 stat_of("photons", "gathers") > 0);
    CHECK(t, !same_image("photons", "gathered"));
    snprintf(words, sizeof words, "%s --accurate-distance 0" PLAIN_BOX, common);
    CHECK(t, render(words, "photons"));
    snprintf(words, sizeof words, "%s --accurate-distance 0 --no-corner-photons" PLAIN_BOX,
             common);
    CHECK(t, render(words, "gathered"));
    CHECK(t, same_image("photons", "gathered"));
    snprintf(words, sizeof words, "%s --paper --corner-photons" PLAIN_BOX, common);
    CHECK(t, render(words, "photons"));
    snprintf(words, sizeof words, "%s --paper" PLAIN_BOX, common);
    CHECK(t, render(words, "gathered"));
    CHECK(t, stat_of("gathered", "gathers") > stat_of("photons", "gathers"));
    remove_render("photons");
    remove_render("gathered");
}

/* truth: Ward 1988's R is the harmonic mean distance of the gather's strata: 2 when every
 *   stratum meets a surface 2 away, whatever the radiances; with the limit on, a gather
 *   that sees light through one sector of twelve alone changes fast across the point and
 *   gets a smaller R. Without bounds, R may lie anywhere from the ray offset at p, 1e-9 x
 *   |p|'s largest coordinate (geom/ray.h), to the scene's diagonal; bounded, from 1.5
 *   pixel footprints / a (test_cache.c has the numbers).
 * tolerance: none (R = 2 is exact: 48 / (48 / 2)), 1e-12 relative for the bounds.
 * catches: --no-gradient-limit that still limits, a limit that acts where the gradient is
 *   small, --no-bounded-reach that keeps a bound of the camera's view. */
static void test_record_reach(struct check *t)
{
    enum { M = 4, N_PHI = 12 };
    struct stratum_sample samples[M * N_PHI];
    for (int i = 0; i < M * N_PHI; i++) {
        samples[i].radiance = i % N_PHI == 0 ? vec3(10, 10, 10) : vec3_zero();
        samples[i].distance = 2;
    }
    struct vec3 n = vec3(0, 0, 1), tx = vec3(1, 0, 0), ty = vec3(0, 1, 0), p = vec3_zero();
    struct record_reach ward = {0.01, 100, 0}, limited = {0.01, 100, 1};
    CHECK(t, irradiance_record_of(p, tx, ty, n, M, N_PHI, samples, ward).r == 2);
    double r = irradiance_record_of(p, tx, ty, n, M, N_PHI, samples, limited).r;
    CHECK(t, r < 2 && r >= 0.01);
    for (int i = 0; i < M * N_PHI; i++)
        samples[i].radiance = vec3(1, 1, 1); /* no gradient: the limit does not act */
    CHECK(t, irradiance_record_of(p, tx, ty, n, M, N_PHI, samples, limited).r == 2);
    struct camera c;
    memset(&c, 0, sizeof c); /* a pinhole: no lens */
    c.from = vec3(0, 0, 0);
    c.at = vec3(0, 0, 1);
    c.up = vec3(0, 1, 0);
    c.fov = 90;
    camera_setup(&c, 100, 100);
    struct vec3 at = vec3(0, 0, 10), facing = vec3(0, 0, -1);
    struct record_reach free_reach = record_reach_at(&c, at, facing, 0.15, 1000, 0, 1);
    CHECK_CLOSE(t, free_reach.r_min, 1e-8, 1e-12 * 1e-8);
    CHECK(t, free_reach.r_max == 1000 && free_reach.gradient_limit == 1);
    struct record_reach bounded = record_reach_at(&c, at, facing, 0.15, 1000, 1, 0);
    CHECK_CLOSE(t, bounded.r_min, 1.5 * 0.2 / 0.15, 1e-12 * 2);
    CHECK(t, bounded.r_max == 200 && bounded.gradient_limit == 0);
}

/* truth: without the floor of 1.5 pixel footprints / a, records near the Cornell box's
 *   creases (where the harmonic mean distance falls towards 0) reach less than a pixel,
 *   so the final pass's samples, away from the pixel centres the pre-pass made records
 *   at, find none usable and gather on the spot: more gather_fallbacks (24 x 24: 356 and
 *   406 against 43). With records free to be small, the gradient's limit is what shrinks
 *   them where irradiance changes fast: without it fewer records fill the cache (48 x 48:
 *   1,284 against 1,429). At these sizes the bounded reach's floor exceeds every
 *   gradient-limited R, so the limit is measured without it.
 * catches: either switch ignored by a mode, or turned the wrong way. */
static void test_reach_switches(struct check *t)
{
    static const char *const modes[] = {"--mode 1994 " TINY, "--mode 1996 " TINY_1996};
    static const char *const larger_modes[] = { /* the same at 48 x 48: a size is given once */
        "--mode 1994 --width 48 --height 48 " TINY_WORK,
        "--mode 1996 --width 48 --height 48 " TINY_WORK " --caustic-photons 20000"};
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        char words[512];
        snprintf(words, sizeof words, "%s" PLAIN_BOX, modes[i]);
        CHECK(t, render(words, "bounded"));
        snprintf(words, sizeof words, "%s --no-bounded-reach" PLAIN_BOX, modes[i]);
        CHECK(t, render(words, "free"));
        CHECK(t, stat_of("free", "gather_fallbacks") > 2 * stat_of("bounded", "gather_fallbacks"));
        const char *larger = "--crop 0 0 8 8 --no-bounded-reach";
        snprintf(words, sizeof words, "%s %s" PLAIN_BOX, larger_modes[i], larger);
        CHECK(t, render(words, "limited"));
        snprintf(words, sizeof words, "%s %s --no-gradient-limit" PLAIN_BOX, larger_modes[i],
                 larger);
        CHECK(t, render(words, "unlimited"));
        CHECK(t, stat_of("unlimited", "cache_records") < stat_of("limited", "cache_records") &&
                     stat_of("unlimited", "cache_records") > 0);
        CHECK(t, !same_image("limited", "unlimited"));
    }
    remove_render("bounded");
    remove_render("free");
    remove_render("limited");
    remove_render("unlimited");
}

void test_switches(struct check *t)
{
    RUN_TEST(t, test_caustic_radius_fraction);
    RUN_TEST(t, test_max_radius);
    RUN_TEST(t, test_both_lobes);
    RUN_TEST(t, test_glossy_corner);
    RUN_TEST(t, test_corner_photons);
    RUN_TEST(t, test_record_reach);
    RUN_TEST(t, test_reach_switches);
}
