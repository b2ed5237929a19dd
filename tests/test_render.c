/*
 * tests/test_render.c -- rendering with --mode direct: closed forms, crops, determinism,
 * and robustness to the scale of the scene.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../src/image/compare.h"
#include "../src/modes/direct.h"
#include "files.h"
#include "tests.h"
#include "truths.h"

static struct image *render(const struct scene *scene, const struct render_settings *rs)
{
    struct render_counters counters = {0, 0, 0, 0};
    return render_direct(scene, rs, 0, NULL, &counters).image;
}

/* truth: the closed form L(x) = rho Phi h / (4 pi^2 d^3) for a point light over a plane.
 *   A pixel is the mean of L over its square, so it must lie between the least and the
 *   greatest L on that square (taken on a 9 x 9 grid that includes the corners; L is
 *   smooth and varies monotonically across a pixel this size, so the grid finds them).
 * tolerance: that interval, widened by 1e-12 relative for rounding.
 * catches: a missing cos, 1/(4 pi) or 1/pi; the inverse-square law wrong; the light's
 *   power read as intensity; a shadow ray blocked by the plane itself (acne). */
static void test_point_light_over_plane(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/analytic/point-over-plane.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_settings rs = render_settings_whole(scene, 1, 4, 16);
    struct image *img = render(scene, &rs);
    CHECK(t, within_point_over_plane(scene, img));
    image_free(img);
    scene_free(scene);
}

/* truth: the light quad emits its radiance (17, 12, 4) and reflects nothing, so a pixel
 *   wholly inside its image is exactly that (pixel (128, 36) is: the light spans rows
 *   32-40 and columns 107-149 at 256 x 256).
 * tolerance: none: every sample returns Le exactly.
 * catches: the light reflecting light, emission from its back, emission lost. */
static void test_light_seen_directly(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell.scene", 0, 0);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_settings rs = render_settings_whole(scene, 1, 4, 16);
    rs.x0 = 128;
    rs.y0 = 36;
    rs.x1 = 129;
    rs.y1 = 37;
    struct image *img = render(scene, &rs);
    struct vec3 v = image_get(img, 0, 0);
    CHECK(t, v.x == 17 && v.y == 12 && v.z == 4);
    image_free(img);
    scene_free(scene);
}

/* truth: render.h's promise: a crop is the same window of the whole image, bit for bit,
 *   and two renders with the same seed are identical.
 * catches: random streams keyed by the crop's own pixel numbers, state carried between
 *   pixels (a shared rng), uninitialised pixels. */
static void test_crop_matches_whole_image(struct check *t)
{
    struct scene *scene = load_test_scene("scenes/cornell.scene", 40, 30);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_settings rs = render_settings_whole(scene, 1, 2, 16);
    struct image *whole = render(scene, &rs);
    struct image *again = render(scene, &rs);
    CHECK(t, memcmp(whole->pixels, again->pixels, 40 * 30 * sizeof *whole->pixels) == 0);
    rs.x0 = 7;
    rs.y0 = 3;
    rs.x1 = 31;
    rs.y1 = 29;
    struct image *crop = render(scene, &rs);
    for (int y = 0; y < crop->height; y++)
        for (int x = 0; x < crop->width; x++) {
            struct vec3 a = image_get(crop, x, y), b = image_get(whole, x + 7, y + 3);
            CHECK(t, a.x == b.x && a.y == b.y && a.z == b.z);
        }
    image_free(crop);
    image_free(again);
    image_free(whole);
    scene_free(scene);
}

/* truth: radiance is invariant under scaling the whole scene (solid angles and the light's
 *   radiance do not change), and the random numbers are the same, so the Cornell box in
 *   metres (x 1e-3) and in micrometres (x 1e3) must give the millimetre image.
 * tolerance: relmse 1e-6 against the unscaled image. Rounding differs between the scales
 *   (1e-3 is not a binary fraction), which can move a sample that grazes an edge; acne
 *   (surfaces shadowing themselves) or light leaking past the walls changes thousands
 *   of samples and gives a relmse above 1e-3.
 * catches: a fixed ray-offset epsilon (acne at 1e3, leaks at 1e-3), a fixed t_min, a
 *   shadow-ray end pulled in by an absolute amount. */
static void test_scale_invariance(struct check *t)
{
    static const char *scaled[] = {"scenes/cornell-1e-3.scene", "scenes/cornell-1e3.scene"};
    struct scene *scene = load_test_scene("scenes/cornell.scene", 64, 64);
    CHECK(t, scene != NULL);
    if (scene == NULL)
        return;
    struct render_settings rs = render_settings_whole(scene, 1, 4, 16);
    struct image *reference = render(scene, &rs);
    scene_free(scene);
    for (int i = 0; i < 2; i++) {
        scene = load_test_scene(scaled[i], 64, 64);
        CHECK(t, scene != NULL);
        if (scene == NULL)
            break;
        struct image *img = render(scene, &rs);
        CHECK(t, image_compare(img, reference).relmse <= 1e-6);
        image_free(img);
        scene_free(scene);
    }
    image_free(reference);
}

/* truth: a procedural shape and its expansion into plain primitives (the `expand` word)
 *   are the same surfaces computed by the same sphere and triangle routines, so the whole
 *   pipeline -- parser, BVH, shading, lights -- must give the same image, bit for bit.
 * catches: a keyword that reads its parameters differently in the two forms, a shape that
 *   reports another normal or material than its primitives, a shadow test that treats
 *   shapes differently. */
static void test_shapes_render_as_their_expansions(struct check *t)
{
    static const char *objects[] = {
        "sphereflake 0 0 0 0.5 2  0 0 1  m n", "heightfield -1 -0.6 -1 2 17 4 0.5 2 0.3 3 m"};
    const char *path = "build/test_render_shape.scene";
    for (int i = 0; i < 2; i++) {
        struct image *img[2] = {NULL, NULL};
        for (int expand = 0; expand < 2; expand++) {
            char text[1024];
            sprintf(text, "camera 0.3 1.2 -2.5  0 0 0  0 1 0  40\n"
                          "material m lambert 0.8 0.5 0.3\nmaterial n mirror 0.9 0.9 0.9\n"
                          "%s%s\nlight point 1 3 -2  100 100 100\n"
                          "light quad -1 2 -1  1 2 -1  1 2 1  -1 2 1  3 3 3\n",
                    objects[i], expand ? " expand" : "");
            write_text_file(path, text);
            struct scene *scene = load_test_scene(path, 40, 40);
            CHECK(t, scene != NULL);
            if (scene == NULL)
                break;
            struct render_settings rs = render_settings_whole(scene, 1, 2, 16);
            img[expand] = render(scene, &rs);
            scene_free(scene);
        }
        CHECK(t, img[0] != NULL && img[1] != NULL &&
                     memcmp(img[0]->pixels, img[1]->pixels, 40 * 40 * sizeof *img[0]->pixels)
                         == 0);
        int lit = 0; /* the shape must be in the picture, lit, for the test to mean anything */
        for (int k = 0; img[0] != NULL && k < 40 * 40; k++)
            lit += img[0]->pixels[k].x > 0.01;
        CHECK(t, lit > 200);
        image_free(img[0]);
        image_free(img[1]);
    }
    remove(path);
}

void test_render(struct check *t)
{
    RUN_TEST(t, test_point_light_over_plane);
    RUN_TEST(t, test_light_seen_directly);
    RUN_TEST(t, test_crop_matches_whole_image);
    RUN_TEST(t, test_scale_invariance);
    RUN_TEST(t, test_shapes_render_as_their_expansions);
}
