/*
 * tests/test_export_output.c -- the export_output room: what `photon export` writes is
 * the image a reference was rendered at (--width, --height), into a file whose ending says
 * its format (.pbrt, .xml, .py): a name that says another, or only the ending, is refused
 * before anything is written.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/vec3.h"
#include "check.h"
#include "files.h"
#include "tests.h"

#define NAME_BYTES 256
#define ARGS_BYTES 1024

/* By format: --format's word, its ending, and the image size as the file gives it, for a
 * printf of width and height. */
static const struct {
    const char *format, *ending, *size;
} formats[] = {
    {"pbrt", ".pbrt", "\"integer xresolution\" [%d] \"integer yresolution\" [%d]"},
    {"mitsuba", ".xml", "<integer name=\"width\" value=\"%d\"/>\n"
                        "            <integer name=\"height\" value=\"%d\"/>"},
    {"blender", ".py", "\nsettings(%d, %d, 1024)\n"},
};
#define N_FORMATS (sizeof formats / sizeof formats[0])

/* Removes the export out and, for Mitsuba, the mesh files beside it. */
static void remove_export(const char *out)
{
    char command[ARGS_BYTES];
    snprintf(command, sizeof command, "rm -f '%s' '%.*s'-mesh*.obj", out,
             (int)(strrchr(out, '.') - out), out);
    run_command(command);
}

/* Exports the Cornell box (256 x 256) in format f with words to out: whether the file
 * says the image is width x height. */
static int exported_size(size_t f, const char *words, const char *out, const char *log,
                         int width, int height)
{
    char args[ARGS_BYTES], size[256];
    snprintf(args, sizeof args, "--format %s %s scenes/cornell.scene -o %s", formats[f].format,
             words, out);
    snprintf(size, sizeof size, formats[f].size, width, height);
    int said = photon_logged("export", args, log) == 0 && file_contains(out, size);
    remove_export(out);
    return said;
}

/* truth: export.h: --width and --height replace the scene's image size in the file each
 *   format writes (pbrt-v4's film, Mitsuba 3's film, Blender's render settings), each
 *   alone keeping the scene's other side, as the render command's do (main.c), with the
 *   render command's range and message for a value out of it.
 * catches: the options read but the scene's 256 x 256 written; a size given to the film
 *   but not to the camera's setup (the pbrt field of view of a wide image); a range of
 *   export's own. */
static void test_size_carried(struct check *t)
{
    char out[NAME_BYTES], log[NAME_BYTES];
    temp_name(log, sizeof log, "export_output", "size.log");
    for (size_t f = 0; f < N_FORMATS; f++) {
        char what[32];
        snprintf(what, sizeof what, "size%s", formats[f].ending);
        temp_name(out, sizeof out, "export_output", what);
        CHECK(t, exported_size(f, "", out, log, 256, 256));
        CHECK(t, exported_size(f, "--width 123 --height 45", out, log, 123, 45));
        CHECK(t, exported_size(f, "--height 45", out, log, 256, 45));
        CHECK(t, exported_size(f, "--width 7", out, log, 7, 256));
    }
    /* The camera is set up for the size given: a tall image's pbrt fov is its shorter,
     * horizontal side's, 2 atan(tan(39.3077 / 2 degrees) 45 / 123), not the scene's
     * vertical 39.3077 that a camera set up for 256 x 256 would give. */
    char args[ARGS_BYTES];
    temp_name(out, sizeof out, "export_output", "fov.pbrt");
    snprintf(args, sizeof args, "--format pbrt --width 45 --height 123 scenes/cornell.scene "
             "-o %s", out);
    CHECK(t, photon_logged("export", args, log) == 0);
    char *text = read_text_file(out);
    const char *fov = text != NULL ? strstr(text, "\"float fov\" [") : NULL;
    double degrees = 0;
    CHECK(t, fov != NULL && sscanf(fov + strlen("\"float fov\" ["), "%lf", &degrees) == 1);
    CHECK_CLOSE(t, degrees, 2 * atan(tan(39.3077 / 2 * PI / 180) * 45 / 123) * 180 / PI, 1e-9);
    free(text);
    remove_export(out);
    CHECK(t, photon_logged("", "--width 0 scenes/cornell.scene", log) == 2 &&
             file_contains(log, "--width: expected a whole number from 1 to 32768, got '0'"));
    static const char *const refused[][2] = {
        {"--width 0", "export: --width: expected a whole number from 1 to 32768, got '0'"},
        {"--height 32769", "export: --height: expected a whole number from 1 to 32768"},
        {"--width 1.5", "export: --width: expected a whole number"},
        {"--height", "export: --height needs a value"},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        snprintf(args, sizeof args, "--format pbrt scenes/cornell.scene -o %s %s", out,
                 refused[i][0]);
        CHECK(t, photon_logged("export", args, log) == 2 && file_contains(log, refused[i][1]) &&
                 !file_exists(out));
    }
    remove(log);
}

/* truth: export.c: -o's name ends in the format's ending (pbrt .pbrt, mitsuba .xml,
 *   blender .py) after a name of its own; else "photon: export: -o: expected a file name
 *   ending in ..." on stderr, exit status 2, and nothing created (no output, no Mitsuba
 *   mesh file, no temporary), checked in a folder of its own that must stay empty.
 * catches: a pbrt scene written as x.xml (opened by the wrong program), a hidden file
 *   ".xml" of no name, the refusal coming after the meshes were written. */
static void test_ending_says_the_format(struct check *t)
{
    char dir[NAME_BYTES], log[NAME_BYTES], args[ARGS_BYTES], command[ARGS_BYTES];
    temp_name(dir, sizeof dir, "export_output", "ending");
    temp_name(log, sizeof log, "export_output", "ending.log");
    snprintf(command, sizeof command, "rm -rf '%s' && mkdir '%s'", dir, dir);
    REQUIRE(t, run_command(command) == 0);
    for (size_t f = 0; f < N_FORMATS; f++) {
        const char *other = formats[(f + 1) % N_FORMATS].ending;
        char names[3][NAME_BYTES + 16], expected[96];
        snprintf(names[0], sizeof names[0], "%s/x%s", dir, other); /* another's ending */
        snprintf(names[1], sizeof names[1], "%s/%s", dir, formats[f].ending); /* it alone */
        snprintf(names[2], sizeof names[2], "%s/x%s.txt", dir, formats[f].ending);
        snprintf(expected, sizeof expected, "photon: export: -o: expected a file name ending "
                 "in %s for --format %s", formats[f].ending, formats[f].format);
        for (int k = 0; k < 3; k++) {
            snprintf(args, sizeof args, "--format %s scenes/cornell.scene -o '%s'",
                     formats[f].format, names[k]);
            CHECK(t, photon_logged("export", args, log) == 2 && file_contains(log, expected));
        }
        snprintf(args, sizeof args, "--format %s scenes/cornell.scene -o %s", formats[f].format,
                 formats[f].ending); /* in the current directory: none may appear there */
        CHECK(t, photon_logged("export", args, log) == 2 && file_contains(log, expected) &&
                 !file_exists(formats[f].ending));
    }
    snprintf(command, sizeof command, "test -z \"$(ls -A '%s')\"", dir);
    CHECK(t, run_command(command) == 0);
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    run_command(command);
    remove(log);
}

void test_export_output(struct check *t)
{
    RUN_TEST(t, test_size_carried);
    RUN_TEST(t, test_ending_says_the_format);
}
