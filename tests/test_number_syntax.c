/*
 * tests/test_number_syntax.c -- one number syntax for every reader (base/number.h): the
 * command line, scene files, NFF, OBJ, PFM headers, crop records and CSV files take and
 * refuse the same strings, as the table below writes them down.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/app/tile.h"
#include "../src/base/number.h"
#include "../src/image/csv.h"
#include "../src/image/image.h"
#include "../src/scene/nff.h"
#include "../src/scene/obj.h"
#include "../src/scene/scene.h"
#include "files.h"
#include "option_words.h"
#include "tests.h"

#define OUT "build/test_number_syntax"

/* The grammar as number.h states it, written out by hand: each string, whether it is a
 * whole number, whether it is a real one, and its value when it is either. */
struct written {
    const char *text;
    int whole, real;
    double value;
};

static const struct written grammar[] = {
    {"16", 1, 1, 16},         {"1", 1, 1, 1},         {"007", 1, 1, 7},
    {"-3", 1, 1, -3},         {"0", 1, 1, 0},         {"99999999999999999999", 1, 1, 1e20},
    {"+5", 0, 1, 5},          {"+1", 0, 1, 1},        {"2.0", 0, 1, 2},
    {"1e2", 0, 1, 100},       {"1e1", 0, 1, 10},      {"1E+2", 0, 1, 100},
    {"1.0e-05", 0, 1, 1e-5},  {"-0.5", 0, 1, -0.5},   {".5", 0, 1, 0.5},
    {"5.", 0, 1, 5},          {"-2.5E-3", 0, 1, -0.0025},
    {"0e-400", 0, 1, 0},      {"0.000e999", 0, 1, 0}, {"4.9e-324", 0, 1, 4.9e-324},
    {"0x10", 0, 0, 0},        {"0x8", 0, 0, 0},       {"0x1", 0, 0, 0},
    {"0x1p1", 0, 0, 0},       {"1e-400", 0, 0, 0},    {"-1e-400", 0, 0, 0},
    {"1e999", 0, 0, 0},       {"inf", 0, 0, 0},       {"-inf", 0, 0, 0},
    {"infinity", 0, 0, 0},    {"nan", 0, 0, 0},       {"1e", 0, 0, 0},
    {"e5", 0, 0, 0},          {".", 0, 0, 0},         {"-", 0, 0, 0},
    {"1.2.3", 0, 0, 0},       {"5x", 0, 0, 0},        {"--5", 0, 0, 0},
    {" 5", 0, 0, 0},          {"5 ", 0, 0, 0},        {"", 0, 0, 0},
};

#define N_GRAMMAR (sizeof grammar / sizeof grammar[0])

/* Whether a reader that splits at white space can be handed the string as one word. */
static int one_word(const char *text)
{
    return text[0] != '\0' && strchr(text, ' ') == NULL;
}

/* Whether the table says a reader of (whole) numbers in [lo, hi] takes the string. */
static int expected(const struct written *w, int whole, double lo, double hi)
{
    return (whole ? w->whole : w->real) && w->value >= lo && w->value <= hi;
}

/* Reports a string a reader judged against the table; returns whether it agreed. */
static int agrees(const char *reader, const struct written *w, int accepted, int expect,
                  const struct error *err)
{
    if (accepted != expect)
        fprintf(stderr, "test_number_syntax: %s %s '%s' (%s)\n", reader,
                accepted ? "took" : "refused", w->text, accepted ? "" : err->message);
    return accepted == expect;
}

/* truth: the table above, from number.h's grammar: whole numbers are digits after an
 *   optional '-'; reals add '+', one '.', an exponent; no hex, inf, nan, white space; a
 *   value beyond a double (1e999) or rounding to 0 from digits not all 0 (1e-400) refused.
 * catches: strtod's syntax let through (hex floats, inf, leading space), "2.0" or "1e2"
 *   taken as whole, an underflow to 0 or a denormal mistaken for one. */
static void test_the_grammar(struct check *t)
{
    for (size_t i = 0; i < N_GRAMMAR; i++) {
        double whole, real;
        int w = number_read(grammar[i].text, 1, &whole) == NUMBER_OK;
        int r = number_read(grammar[i].text, 0, &real) == NUMBER_OK;
        CHECK(t, w == grammar[i].whole && r == grammar[i].real);
        CHECK(t, !r || real == grammar[i].value);
        if (w != grammar[i].whole || r != grammar[i].real)
            fprintf(stderr, "test_number_syntax: '%s' whole %d real %d\n", grammar[i].text, w, r);
    }
    double v;
    CHECK(t, number_read("1e-400", 0, &v) == NUMBER_UNDERFLOW && v == 0);
    CHECK(t, number_read("1e999", 0, &v) == NUMBER_INFINITE);
    CHECK(t, number_read("nan", 0, &v) == NUMBER_INFINITE);
    CHECK(t, number_read("0x10", 0, &v) == NUMBER_UNWRITTEN);
}

/* Loads a scene file of a camera, a material and line; whether it loaded. */
static int scene_takes(const char *line, struct error *err)
{
    char text[256];
    snprintf(text, sizeof text, "camera 0 0 0 0 0 1 0 1 0 40\nmaterial m lambert 0.5 0.5 "
             "0.5\n%s\n", line);
    write_text_file(OUT ".scene", text);
    struct scene *scene = scene_load(OUT ".scene", err);
    scene_free(scene);
    return scene != NULL;
}

/* truth: the table: `image W 8` takes the whole numbers from 1 to MAX_IMAGE_SIDE, a
 *   sphere's centre x any real (none of the table's values lies between 1e6 and the 2^40
 *   a scene may reach); sphereflake levels and heightfield octaves whole numbers too.
 * catches: the scene reader's own strtod (image 0x8 8, image 1e1 8, sphere 0x1p1 ...). */
static void test_scene_files(struct check *t)
{
    for (size_t i = 0; i < N_GRAMMAR; i++) {
        const struct written *w = &grammar[i];
        if (!one_word(w->text))
            continue;
        char line[160];
        struct error err;
        snprintf(line, sizeof line, "image %s 8", w->text);
        CHECK(t, agrees("image", w, scene_takes(line, &err),
                        expected(w, 1, 1, MAX_IMAGE_SIDE), &err));
        snprintf(line, sizeof line, "sphere %s 0 5 1 m", w->text);
        CHECK(t, agrees("sphere", w, scene_takes(line, &err), expected(w, 0, -1e6, 1e6), &err));
    }
    struct error err;
    CHECK(t, scene_takes("sphereflake 0 0 5 1 1 0 1 0 m", &err));
    CHECK(t, !scene_takes("sphereflake 0 0 5 1 1.0 0 1 0 m", &err) &&
             strstr(err.message, "'1.0' is not a whole number") != NULL);
    CHECK(t, !scene_takes("heightfield 0 0 0 1 4 2e0 0.5 1 0.1 7 m", &err));
    CHECK(t, !scene_takes("image 8 8.0", &err) && strstr(err.message, "whole numbers"));
}

#define VIEW_TO_ANGLE "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\n"

/* Loads an NFF file; whether it loaded. */
static int nff_takes(const char *text, struct error *err)
{
    write_text_file(OUT ".nff", text);
    struct scene *scene = nff_load(OUT ".nff", err);
    scene_free(scene);
    return scene != NULL;
}

/* truth: the table: NFF's resolution takes whole numbers from 1 to MAX_IMAGE_SIDE, a
 *   sphere's centre x any real, a polygon's vertex count whole numbers only.
 * catches: NFF's own strtod ("resolution 0x8 6", "s 0x1p1 ...", "p 3.0"). */
static void test_nff_files(struct check *t)
{
    for (size_t i = 0; i < N_GRAMMAR; i++) {
        const struct written *w = &grammar[i];
        if (!one_word(w->text))
            continue;
        char text[256];
        struct error err;
        snprintf(text, sizeof text, VIEW_TO_ANGLE "resolution %s 6\nf 1 1 1 1 0 0 0 0\n"
                 "s 0 0 0 1\n", w->text);
        CHECK(t, agrees("NFF resolution", w, nff_takes(text, &err),
                        expected(w, 1, 1, MAX_IMAGE_SIDE), &err));
        snprintf(text, sizeof text, VIEW_TO_ANGLE "resolution 8 6\nf 1 1 1 1 0 0 0 0\n"
                 "s %s 0 0 1\n", w->text);
        CHECK(t, agrees("NFF s", w, nff_takes(text, &err), expected(w, 0, -1e6, 1e6), &err));
    }
    struct error err;
    CHECK(t, !nff_takes(VIEW_TO_ANGLE "resolution 8 6\nf 1 1 1 1 0 0 0 0\n"
                        "p 3.0\n0 0 0\n1 0 0\n0 1 0\n", &err) &&
             strstr(err.message, "'3.0' is not a whole number"));
}

/* Imports an OBJ file at scale 1 into a scene with one material; whether it was taken. */
static int obj_takes(const char *text, struct error *err)
{
    write_text_file(OUT ".obj", text);
    struct scene *scene = scene_create();
    struct material m;
    memset(&m, 0, sizeof m);
    m.kind = MATERIAL_LAMBERT;
    m.rho = vec3(0.5, 0.5, 0.5);
    scene_add_material(scene, &m);
    struct obj_placement place = obj_unmoved(0);
    int taken = obj_import(scene, OUT ".obj", &place, err) == 0;
    scene_free(scene);
    return taken;
}

/* truth: the table, and the OBJ specification (Wavefront's appendix B1): coordinates are
 *   reals ("1.0e-05", "-0.5" as other tools write them); a face's reference numbers are
 *   integers, negative ones (relative to the last vertex) written with '-', no '+'; with
 *   three vertices defined, 1..3 and -1..-3 name one. Standard corners (1/2/3, 1//1,
 *   negative indices) still load.
 * catches: OBJ's own strtod and strtol ("v 0x1 0 0", "f +1 2 3", "f 1e0 2 3"). */
static void test_obj_files(struct check *t)
{
    for (size_t i = 0; i < N_GRAMMAR; i++) {
        const struct written *w = &grammar[i];
        if (!one_word(w->text))
            continue;
        char text[256];
        struct error err;
        snprintf(text, sizeof text, "v %s 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\n", w->text);
        CHECK(t, agrees("OBJ v", w, obj_takes(text, &err), expected(w, 0, -1e30, 1e30), &err));
        snprintf(text, sizeof text, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf %s 2 3\n", w->text);
        int named = expected(w, 1, 1, 3) || expected(w, 1, -3, -1);
        CHECK(t, agrees("OBJ f", w, obj_takes(text, &err), named, &err));
    }
    struct error err;
    CHECK(t, obj_takes("v 1.0e-05 -0.5 +2\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                       "f 1/1/1 2/1/1 3/1/1\nf 1//1 2//1 3//1\nf -1 -2 -3\nf -3/-1 -2/1 -1/1\n",
                       &err));
}

/* Writes a PFM of the header text and n black pixels; whether pfm_read() takes it. */
static int pfm_takes(const char *header, size_t n, struct error *err)
{
    size_t size = strlen(header) + 12 * n;
    unsigned char *bytes = calloc(size, 1);
    memcpy(bytes, header, strlen(header));
    write_bytes_file(OUT ".pfm", bytes, size);
    free(bytes);
    struct image *image = pfm_read(OUT ".pfm", err);
    image_free(image);
    return image != NULL;
}

/* truth: the table: a PFM header's width is a whole number from 1 to MAX_IMAGE_SIDE
 *   (the file holds that many pixels, or one when the width is refused), its scale any
 *   real but 0 (its sign is the byte order).
 * catches: the header's strtol and strtod ("+4", "0x10", "1e1" as a width). */
static void test_pfm_headers(struct check *t)
{
    for (size_t i = 0; i < N_GRAMMAR; i++) {
        const struct written *w = &grammar[i];
        if (!one_word(w->text))
            continue;
        char header[128];
        struct error err;
        int width_ok = expected(w, 1, 1, MAX_IMAGE_SIDE);
        snprintf(header, sizeof header, "PF\n%s 1\n-1.0\n", w->text);
        CHECK(t, agrees("PFM width", w, pfm_takes(header, width_ok ? (size_t)w->value : 1,
                                                  &err), width_ok, &err));
        snprintf(header, sizeof header, "PF\n1 1\n%s\n", w->text);
        CHECK(t, agrees("PFM scale", w, pfm_takes(header, 1, &err),
                        expected(w, 0, -1e30, 1e30) && w->value != 0, &err));
    }
}

/* Writes a crop record of the image width and time limit given; whether it is read. */
static int record_takes(const char *width, const char *seconds, struct error *err)
{
    char text[512];
    snprintf(text, sizeof text, "photon-window 2\nwindow 0 0 1 1\nimage %s 1\n"
             "hash fnv1a64 0123456789abcdef\npixels fnv1a64 0000000000000000\n"
             "time-limit %s\n", width, seconds);
    write_text_file(OUT "_tile.pfm" TILE_RECORD_SUFFIX, text);
    struct tile_record r;
    return tile_record_read(OUT "_tile.pfm", &r, err) == 0;
}

/* truth: the table: a crop record's sizes are whole numbers (the image's width from 1 to
 *   MAX_IMAGE_SIDE), its time limit a real >= 0.
 * catches: the record's strtod taking "1e-400" (read as 0: no limit) or "0x10". */
static void test_crop_records(struct check *t)
{
    for (size_t i = 0; i < N_GRAMMAR; i++) {
        const struct written *w = &grammar[i];
        if (!one_word(w->text))
            continue;
        struct error err;
        CHECK(t, agrees("record width", w, record_takes(w->text, "0", &err),
                        expected(w, 1, 1, MAX_IMAGE_SIDE), &err));
        CHECK(t, agrees("record time-limit", w, record_takes("1", w->text, &err),
                        expected(w, 0, 0, 1e30), &err));
    }
    remove(OUT "_tile.pfm" TILE_RECORD_SUFFIX);
}

/* Writes a CSV "x,y" with one row "FIELD,1"; whether csv_next_row() takes the row. */
static int csv_takes(const char *field, struct error *err)
{
    char text[128];
    snprintf(text, sizeof text, "x,y\n%s,1\n", field);
    write_text_file(OUT ".csv", text);
    struct csv csv;
    if (csv_open(&csv, OUT ".csv", err) < 0)
        return 0;
    double row[2];
    int taken = csv_next_row(&csv, row, err) == 1;
    csv_close(&csv);
    return taken;
}

/* truth: the table: a CSV field (trimmed of spaces, csv.h, so only one-word strings here)
 *   is any real; the command line's --exposure any real from 0 to 1e30, --spp a whole
 *   number from 1 to 1048576.
 * catches: plot's strtod taking "0x10" or "inf"; the command line and the files
 *   disagreeing. */
static void test_csv_and_command_line(struct check *t)
{
    for (size_t i = 0; i < N_GRAMMAR; i++) {
        const struct written *w = &grammar[i];
        if (!one_word(w->text))
            continue;
        struct error err;
        CHECK(t, agrees("CSV", w, csv_takes(w->text, &err), expected(w, 0, -1e30, 1e30),
                        &err));
        char words[128];
        struct options o;
        snprintf(words, sizeof words, "--exposure %s", w->text);
        snprintf(err.message, sizeof err.message, "(see above)");
        CHECK(t, agrees("--exposure", w, options_of(words, &o) == 0, expected(w, 0, 0, 1e30),
                        &err));
        snprintf(words, sizeof words, "--spp %s", w->text);
        CHECK(t, agrees("--spp", w, options_of(words, &o) == 0, expected(w, 1, 1, 1048576),
                        &err));
    }
    run_command("rm -f " OUT ".*");
}

void test_number_syntax(struct check *t)
{
    RUN_TEST(t, test_the_grammar);
    RUN_TEST(t, test_scene_files);
    RUN_TEST(t, test_nff_files);
    RUN_TEST(t, test_obj_files);
    RUN_TEST(t, test_pfm_headers);
    RUN_TEST(t, test_crop_records);
    RUN_TEST(t, test_csv_and_command_line);
}
