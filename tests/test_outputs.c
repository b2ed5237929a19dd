/*
 * tests/test_outputs.c -- the files a command writes and reads (base/output.h,
 * base/input.h): no output destroys an input or another output, an output that cannot be
 * written is refused before any work, a command's outputs appear all or none, and no
 * input makes a reader hang or read past a NUL byte.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/base/output.h"
#include "files.h"
#include "tests.h"

#define COMMAND_MAX 2048
#define OUT "build/test_outputs"
#define TINY "--no-progress --width 4 --height 4 --spp 2 --mode pt"
#define SCENE "scenes/cornell.scene"
/* Runs "PHOTON args" with its output in OUT.log, under timeout(1): a reader that hangs
 * fails its test (status 124) instead of stopping the run. */
static int photon(const char *args)
{
    char command[2 * COMMAND_MAX];
    snprintf(command, sizeof command, "timeout 60 %s %s >" OUT ".log 2>&1", photon_binary(),
             args);
    return run_command(command);
}

static int log_contains(const char *text)
{
    return file_contains(OUT ".log", text);
}

/* Removes every file a test may have left under OUT_*. */
static void clean(void)
{
    run_command("rm -rf " OUT "_*");
}

/* Whether no file or temporary is left under OUT_ but the ones the test made first
 * (ls's count of names matching OUT_* equals n). */
static int files_left(int n)
{
    char command[COMMAND_MAX];
    snprintf(command, sizeof command, "test $(ls -d " OUT "_* 2>/dev/null | wc -l) -eq %d", n);
    return run_command(command) == 0;
}

/* truth: output.h: two outputs of one command that are one file are refused before any
 *   work (status 2, "names the same file as", no file written), whatever pair it is and
 *   however the name is spelt: the same spelling, ./, an absolute path, the PNG beside
 *   -o, the crop's record, the report, the work file. The scene named does not exist, so
 *   only a check made before the scene is read can give that message.
 * catches: -o a.pfm --variance a.pfm writing the variance over the render (exit 0), a
 *   check by spelling only, a pair of roles left out of the check. */
static void test_two_outputs_one_file_refused(struct check *t)
{
    static const char *const pairs[] = {
        "-o " OUT "_a.pfm --variance " OUT "_a.pfm",
        "-o " OUT "_a.png --variance " OUT "_a.pfm",
        "-o " OUT "_a.pfm --variance ./" OUT "_a.png",
        "-o " OUT "_a.pfm --variance $PWD/" OUT "_a.pfm",
        "-o " OUT "_a.pfm --crop 0 0 2 2 --variance " OUT "_a.pfm.window",
        "-o " OUT "_a.pfm --reference " OUT "_r.pfm --report build/../" OUT "_a.pfm",
        "-o " OUT "_a.ppm --mode photons --save-photons " OUT "_a.ppm",
        "-o " OUT "_a.pfm --variance " OUT "_v.pfm --reference " OUT "_r.pfm --report "
        OUT "_v.pfm",
    };
    clean();
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        char command[COMMAND_MAX];
        snprintf(command, sizeof command, "--no-progress %s build/no_such.scene", pairs[i]);
        CHECK(t, photon(command) == 2 && log_contains("names the same file as"));
        CHECK(t, files_left(0));
    }
}

/* truth: output.h: an output that is an input of the command is refused (status 2) and
 *   the input keeps its bytes: the scene itself (also through a symbolic link to it), an
 *   OBJ file the scene reads, a tile given to merge, --reference. A copy of an input with
 *   the same bytes, and a hard link to it, are other directory entries: writing them
 *   destroys nothing, and they pass.
 * catches: export -o SCENE overwriting the scene, merge -o L.pfm L.pfm R.pfm, --reference
 *   r.pfm --report r.pfm; a check by bytes alone refusing a copy (a merge run twice). */
static void test_output_naming_an_input_refused(struct check *t)
{
    clean();
    run_command("cp " SCENE " " OUT "_s.scene && ln -s test_outputs_s.scene " OUT "_link.scene"
                " && cp scenes/mesh.obj " OUT "_mesh.obj");
    write_text_file(OUT "_o.scene", "camera 0 0 -5 0 0 0 0 1 0 40\nmaterial w lambert 1 1 1\n"
                                    "obj test_outputs_mesh.obj w\n");
    CHECK(t, photon(TINY " --crop 0 0 2 4 -o " OUT "_l.pfm " SCENE) == 0);
    CHECK(t, photon(TINY " --crop 2 0 4 4 -o " OUT "_r.pfm " SCENE) == 0);
    run_command("cp " OUT "_s.scene " OUT "_keep.scene && cp " OUT "_l.pfm " OUT "_keep.pfm");
    static const char *const refused[][2] = {
        {"export --format pbrt " OUT "_s.scene -o " OUT "_s.scene", OUT "_s.scene"},
        {"export --format pbrt " OUT "_link.scene -o " OUT "_s.scene", OUT "_s.scene"},
        {"export --format pbrt " OUT "_o.scene -o " OUT "_mesh.obj", OUT "_mesh.obj"},
        {"merge -o " OUT "_l.pfm " OUT "_l.pfm " OUT "_r.pfm", OUT "_l.pfm"},
        {TINY " --reference " OUT "_l.pfm --report " OUT "_l.pfm --crop 0 0 2 4 "
         "-o " OUT "_x.pfm " SCENE, OUT "_l.pfm"},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        CHECK(t, photon(refused[i][0]) == 2 && log_contains("is the input"));
        CHECK(t, files_equal(OUT "_s.scene", OUT "_keep.scene") &&
                 files_equal(OUT "_l.pfm", OUT "_keep.pfm"));
        CHECK(t, !file_exists(OUT "_x.pfm") && no_temporaries(OUT "_s.scene") &&
                 no_temporaries(OUT "_l.pfm"));
    }
    CHECK(t, photon("merge -o " OUT "_m.pfm " OUT "_l.pfm " OUT "_r.pfm") == 0);
    run_command("cp " OUT "_m.pfm " OUT "_copy.pfm && ln " OUT "_m.pfm " OUT "_hard.pfm");
    CHECK(t, photon("merge -o " OUT "_copy.pfm " OUT "_l.pfm " OUT "_r.pfm") == 0);
    CHECK(t, photon("compare " OUT "_copy.pfm " OUT "_m.pfm --diff " OUT "_hard.png") == 0);
    CHECK(t, photon(TINY " -o " OUT "_hard.pfm --reference " OUT "_m.pfm --report "
                    OUT "_x.csv " SCENE) == 0);
    clean();
}

/* truth: output.h: an output that is a directory is refused before any work (status 2,
 *   "is a directory"), for each output of each command: -o, the PNG beside it,
 *   --variance, --report, the crop's record, export's -o, compare's --diff, plot's and
 *   probe's -o, merge's -o, a name ending in '/'; an empty name is refused too. The
 *   inputs do not exist, so the message comes before any is read.
 * catches: the directory found only after the whole render (status 1, no reason). */
static void test_directory_outputs_refused(struct check *t)
{
    static const char *const commands[] = {
        "-o " OUT "_d.pfm build/no_such.scene",
        "-o " OUT "_d.png build/no_such.scene",
        "-o " OUT "_x.pfm --variance " OUT "_d.pfm build/no_such.scene",
        "-o " OUT "_x.pfm --reference r.pfm --report " OUT "_d.pfm build/no_such.scene",
        "-o " OUT "_w.pfm --crop 0 0 1 1 build/no_such.scene",
        "export --format pbrt build/no_such.scene -o " OUT "_d.pfm",
        "compare build/no_such.pfm build/no_such.pfm --diff " OUT "_d.png",
        "plot build/no_such.csv -o " OUT "_d.svg",
        "probe build/no_such.scene --line 0 0 0 1 1 1 --samples 2 -o " OUT "_d.pfm",
        "merge -o " OUT "_d.pfm build/no_such.pfm",
        "-o " OUT "_x.pfm --variance " OUT "_nothere/ build/no_such.scene",
    };
    clean();
    run_command("mkdir " OUT "_d.pfm " OUT "_d.png " OUT "_w.pfm.window " OUT "_d.svg");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        CHECK(t, photon(commands[i]) == 2 && log_contains("is a directory"));
        CHECK(t, files_left(4));
    }
    CHECK(t, photon("-o " OUT "_x.pfm --variance '' build/no_such.scene") == 2 &&
             log_contains("--variance: an empty file name"));
    CHECK(t, photon("-o '' build/no_such.scene") == 2 && log_contains("-o: expected"));
    clean();
}

/* truth: output.h: an existing output that cannot be opened for writing (mode 444) is
 *   refused before any work, status 2, and keeps its bytes. Run as the user nobody when
 *   the tests run as root, for whom every file is writable (setpriv, util-linux).
 * catches: a read-only file replaced silently by the rename of a temporary. */
static void test_read_only_output_refused(struct check *t)
{
    char command[COMMAND_MAX];
    clean();
    run_command("mkdir -m 777 " OUT "_ro && cp " SCENE " " OUT "_ro/s.scene && chmod 644 "
                OUT "_ro/s.scene && echo precious > " OUT "_ro/x.pfm && chmod 444 "
                OUT "_ro/x.pfm");
    snprintf(command, sizeof command, "cd " OUT "_ro && if [ $(id -u) = 0 ]; then "
             "as='setpriv --reuid=nobody --regid=nogroup --clear-groups'; else as=; fi; "
             "$as %s%s " TINY " -o x.pfm s.scene > ../test_outputs.log 2>&1",
             photon_binary()[0] == '/' ? "" : "../../", photon_binary());
    CHECK(t, run_command(command) == 2 && log_contains("x.pfm: the file exists and cannot "
                                                       "be written: Permission denied (-o)"));
    CHECK(t, file_equals_text(OUT "_ro/x.pfm", "precious\n") && !file_exists(OUT "_ro/x.png"));
    clean();
}

/* truth: output.h: a command's outputs appear all or none. Here every output was checked
 *   and written whole, and the second rename fails (its name became a directory after the
 *   check): the first output, already renamed, is removed, and no temporary is left.
 * catches: outputs renamed one by one as they are written, the first left in place. */
static void test_outputs_all_or_none(struct check *t)
{
    struct error err;
    clean();
    outputs_abandon(); /* the inputs earlier tests of this process read are forgotten */
    output_declare(OUT "_first.txt", "first");
    output_declare(OUT "_second.txt", "second");
    REQUIRE(t, outputs_check(&err) == 0);
    static const char *const names[] = {OUT "_first.txt", OUT "_second.txt"};
    for (int i = 0; i < 2; i++) {
        FILE *f = output_open(names[i], &err);
        REQUIRE(t, f != NULL);
        fputs("bytes\n", f);
        CHECK(t, output_commit(f, &err) == 0);
    }
    CHECK(t, !file_exists(OUT "_first.txt")); /* nothing is in place before the publish */
    run_command("mkdir " OUT "_second.txt && touch " OUT "_second.txt/inside");
    CHECK(t, outputs_publish(&err) < 0 && err.failed_write);
    CHECK(t, !file_exists(OUT "_first.txt") && files_left(1));
    outputs_abandon();
    clean();
}

/* truth: README's export: any scene exports; Mitsuba's meshes go in files beside the
 *   XML, one a mesh, each named in the XML. The museum has more meshes than photon once
 *   held open at once.
 * catches: "too many outputs open at once" for a scene of many meshes. */
static void test_museum_exports_to_mitsuba(struct check *t)
{
    clean();
    CHECK(t, photon("export --format mitsuba scenes/museum.scene -o " OUT "_m.xml") == 0);
    CHECK(t, run_command("n=$(ls " OUT "_m-mesh*.obj | wc -l); test $n -gt 8 && "
                         "test $n -eq $(grep -c 'type=\"obj\"' " OUT "_m.xml)") == 0);
    clean();
}

/* truth: input.h: a reader takes only regular files and reads them to their size: a
 *   device such as /dev/zero (which says its size is 0 and gives bytes for ever), named
 *   as the scene, an include, an OBJ or NFF file, a PFM, a CSV or a tile, is refused
 *   with status 2 and its name, within the time limit; a directory an include names is
 *   refused at the line that names it.
 * catches: a reader that reads /dev/zero for ever (the tests' timeout ends it: status
 *   124), "include DIR" reported without the including file and line. */
static void test_inputs_must_be_regular_files(struct check *t)
{
    static const char *const lines[][2] = {
        {"include /dev/zero", ":3: include: cannot open '/dev/zero': not a regular file"},
        {"obj /dev/zero w", ":3: obj: cannot open '/dev/zero': not a regular file"},
        {"nff /dev/zero", ":3: nff: cannot open '/dev/zero': not a regular file"},
        {"include /tmp", ":3: include: cannot open '/tmp': is a directory"},
    };
    clean();
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        char text[256];
        snprintf(text, sizeof text, "camera 0 0 0 0 0 1 0 1 0 40\nmaterial w lambert 1 1 1\n"
                 "%s\n", lines[i][0]);
        write_text_file(OUT "_z.scene", text);
        CHECK(t, photon(TINY " -o " OUT "_x.pfm " OUT "_z.scene") == 2 &&
                 log_contains(lines[i][1]));
    }
    run_command("touch " OUT "_t.pfm && ln -s /dev/zero " OUT "_t.pfm.window");
    static const char *const commands[] = {
        TINY " -o " OUT "_x.pfm /dev/zero",
        TINY " -o " OUT "_x.pfm --reference /dev/zero --report " OUT "_x.csv " SCENE,
        "compare /dev/zero /dev/zero",
        "plot /dev/zero -o " OUT "_x.svg",
        "merge -o " OUT "_x.pfm " OUT "_t.pfm",
        "--no-progress --width 4 --height 4 --mode photons --load-photons /dev/zero -o " OUT
            "_x.pfm " SCENE,
    };
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        CHECK(t, photon(commands[i]) == 2 && log_contains("/dev/zero") &&
                 log_contains("not a regular file"));
        CHECK(t, !file_exists(OUT "_x.pfm"));
    }
    clean();
}

/* truth: input.h: a NUL byte in a line of any text reader is refused at its file and
 *   line (C's strings would end the line there and take what came before).
 * catches: "sphere 0 1 0 1 w\0garbage" read as "sphere 0 1 0 1 w". */
static void test_nul_byte_refused(struct check *t)
{
    static const unsigned char scene[] = "camera 0 0 -5 0 0 0 0 1 0 40\n"
                                         "material w lambert 1 1 1\n"
                                         "sphere 0 1 0 1 w\0garbage\n";
    static const unsigned char obj[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\0 4\n";
    static const unsigned char nff[] = "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\n"
                                       "hither 1\nresolution 8 8\nf 1 1 1 1 0 0 0 0\n"
                                       "s 0 0 0 1\0 junk\n";
    static const unsigned char csv[] = "seconds,work,rmse,relmse\n1,1,1,1\0,5\n";
    clean();
    write_bytes_file(OUT "_n.scene", scene, sizeof scene - 1);
    write_bytes_file(OUT "_n.obj", obj, sizeof obj - 1);
    write_bytes_file(OUT "_n.nff", nff, sizeof nff - 1);
    write_bytes_file(OUT "_n.csv", csv, sizeof csv - 1);
    write_text_file(OUT "_o.scene", "camera 0 0 -5 0 0 0 0 1 0 40\nmaterial w lambert 1 1 1\n"
                                    "obj test_outputs_n.obj w\n");
    static const char *const commands[][2] = {
        {TINY " -o " OUT "_x.pfm " OUT "_n.scene", OUT "_n.scene:3: a NUL byte"},
        {TINY " -o " OUT "_x.pfm " OUT "_o.scene", OUT "_n.obj:4: a NUL byte"},
        {TINY " -o " OUT "_x.pfm " OUT "_n.nff", OUT "_n.nff:9: a NUL byte"},
        {"plot " OUT "_n.csv -o " OUT "_x.svg", OUT "_n.csv:2: a NUL byte"},
    };
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        CHECK(t, photon(commands[i][0]) == 2 && log_contains(commands[i][1]));
        CHECK(t, !file_exists(OUT "_x.pfm") && !file_exists(OUT "_x.svg"));
    }
    clean();
}

/* truth: image.h: a PFM holds floats, and radiance beyond their range is an error (status
 *   1, a machine's limit reached after the work), not a clamp: a point light of 1e30 W
 *   (the largest power) 1e-6 over a white floor gives E = 1e30 / (4 pi 1e-12) and
 *   L = E / pi, about 2.5e40 > FLT_MAX. Nothing is written. The same floor at 1e-3 with
 *   1 W renders; scaled to 1e-21 the scene is refused at load (reach.h), status 2.
 * catches: pixels clamped to 3.4e38 in an image that claims to be radiance. */
static void test_radiance_beyond_float_refused(struct check *t)
{
    static const char *const scales[][3] = {{"1e-6", "2e-6", "1e30"}, {"1e-3", "2e-3", "1"},
                                            {"1e-21", "2e-21", "1"}};
    static const int status[] = {1, 0, 2};
    clean();
    for (int i = 0; i < 3; i++) {
        char text[512];
        const char *h = scales[i][0], *p = scales[i][2];
        snprintf(text, sizeof text, "image 1 1\ncamera 0 %s 0 0 0 0 0 0 1 1\n"
                 "material w lambert 1 1 1\nquad -%s 0 -%s -%s 0 %s %s 0 %s %s 0 -%s w\n"
                 "light point 0 %s 0 %s %s %s\n", scales[i][1], h, h, h, h, h, h, h, h, h,
                 p, p, p);
        write_text_file(OUT "_f.scene", text);
        CHECK(t, photon("--no-progress -o " OUT "_f.pfm " OUT "_f.scene") == status[i]);
        CHECK(t, file_exists(OUT "_f.pfm") == (status[i] == 0) &&
                 file_exists(OUT "_f.png") == (status[i] == 0));
        CHECK(t, status[i] != 1 || log_contains("beyond a PFM's float range"));
        run_command("rm -f " OUT "_f.p*");
    }
    clean();
}

/* truth: compare --diff follows -o's rule: a PNG for NAME.png, a PPM for NAME.ppm, any
 *   other ending refused (status 2) before the images are read. The 4 x 4 difference is
 *   drawn with its colour bar (false_colour.h): 4 + 27 + 6 x 4 pixels wide for labels of
 *   4 characters, and 60 tall, the least a bar takes.
 * catches: a P6 PPM written into a file named .png. */
static void test_diff_format_by_name(struct check *t)
{
    clean();
    CHECK(t, photon(TINY " -o " OUT "_a.pfm " SCENE) == 0);
    CHECK(t, photon("compare " OUT "_a.pfm " OUT "_a.pfm --diff " OUT "_d.png") == 0 &&
             file_contains(OUT "_d.png", "PNG"));
    CHECK(t, photon("compare " OUT "_a.pfm " OUT "_a.pfm --diff " OUT "_d.ppm") == 0 &&
             file_contains(OUT "_d.ppm", "P6\n55 60\n255\n"));
    CHECK(t, photon("compare build/no_such.pfm " OUT "_a.pfm --diff " OUT "_d.jpg") == 2 &&
             log_contains("--diff") && !file_exists(OUT "_d.jpg"));
    clean();
}

/* Whether the file's first bytes are those of prefix (its '\0' excluded). */
static int starts_with(const char *name, const char *prefix)
{
    char bytes[64] = {0};
    size_t n = strlen(prefix);
    FILE *f = fopen(name, "rb");
    size_t got = f != NULL && n < sizeof bytes ? fread(bytes, 1, n, f) : 0;
    if (f != NULL)
        fclose(f);
    return got == n && memcmp(bytes, prefix, n) == 0;
}

/* Removes the files a render to OUT_NAME may leave: .pfm, .png, .ppm and their temporaries. */
static void remove_outputs(const char *name)
{
    static const char *const endings[] = {".pfm", ".png", ".ppm", ".pfm.tmp", ".png.tmp",
                                          ".ppm.tmp", ".png.pfm", ".ppm.pfm"};
    for (size_t i = 0; i < sizeof endings / sizeof endings[0]; i++) {
        char file[COMMAND_MAX];
        snprintf(file, sizeof file, "%s%s", name, endings[i]);
        remove(file);
    }
}

/* truth: the naming rule of -o (option_values.h, read_output): NAME.pfm is always written, and
 *   beside it NAME.png, or NAME.ppm when -o names one; nothing else. --checkpoint's
 *   snapshots and photon merge follow the same rule. The PFM does not depend on -o's ending.
 * catches: the display image written over the PFM (x.png holding a PFM), a PNG written
 *   besides the PPM asked for, a snapshot or a merge ignoring the ending, x.png.pfm. */
static void test_output_names(struct check *t)
{
    const char *args = "--width 12 --height 8 --spp 1 scenes/cornell.scene";
    char command[COMMAND_MAX];
    remove_outputs(OUT "_name");
    snprintf(command, sizeof command, "-o " OUT "_name.png %s", args);
    CHECK(t, photon(command) == 0);
    CHECK(t, file_exists(OUT "_name.pfm") && file_exists(OUT "_name.png"));
    CHECK(t, !file_exists(OUT "_name.ppm") && !file_exists(OUT "_name.png.pfm"));
    CHECK(t, starts_with(OUT "_name.png", "\211PNG\r\n\032\n") &&
             starts_with(OUT "_name.pfm", "PF\n"));
    rename(OUT "_name.pfm", OUT "_png.pfm");
    remove(OUT "_name.png");
    snprintf(command, sizeof command, "-o " OUT "_name.ppm %s", args);
    CHECK(t, photon(command) == 0);
    CHECK(t, file_exists(OUT "_name.pfm") && file_exists(OUT "_name.ppm"));
    CHECK(t, !file_exists(OUT "_name.png") && starts_with(OUT "_name.ppm", "P6\n12 8\n255\n"));
    CHECK(t, files_equal(OUT "_name.pfm", OUT "_png.pfm"));
    remove_outputs(OUT "_name");
    CHECK(t, photon("--mode 2008 -o " OUT "_name.ppm --width 8 --height 8 --passes 2 "
                    "--photons-per-pass 1000 --checkpoint 1 scenes/cornell.scene") == 0);
    CHECK(t, file_exists(OUT "_name.ppm") && !file_exists(OUT "_name.png"));
    remove_outputs(OUT "_name");
    CHECK(t, photon("--crop 0 0 12 8 -o " OUT "_tile.png --width 12 --height 8 --spp 1 "
                    "scenes/cornell.scene") == 0);
    CHECK(t, file_exists(OUT "_tile.pfm.window") && !file_exists(OUT "_tile.png.window"));
    CHECK(t, photon("merge -o " OUT "_name.ppm " OUT "_tile.pfm") == 0);
    CHECK(t, files_equal(OUT "_name.pfm", OUT "_png.pfm") && file_exists(OUT "_name.ppm") &&
             !file_exists(OUT "_name.png"));
    CHECK(t, photon("merge -o " OUT "_name.png " OUT "_tile.pfm") == 0);
    CHECK(t, files_equal(OUT "_name.png", OUT "_tile.png"));
    CHECK(t, photon("merge -o " OUT "_name.jpg " OUT "_tile.pfm") == 2 &&
             log_contains("-o: expected a file name ending in .pfm, .exr, .png or .ppm"));
    remove_outputs(OUT "_name");
    remove_outputs(OUT "_png");
    remove_outputs(OUT "_tile");
    remove(OUT "_tile.pfm.window");
}

/* truth: with no -o the PFM is named for the scene, without its directory (README), and
 *   the PNG is beside it. Run inside build/ so the files land there.
 * catches: the default naming the PPM, or the PNG put beside the scene file. */
static void test_default_output_names(struct check *t)
{
    const char *binary = photon_binary();
    char command[COMMAND_MAX];
    remove("build/cornell.pfm");
    remove("build/cornell.png");
    snprintf(command, sizeof command, "cd build && %s%s --width 4 --height 4 --spp 1 "
             "../scenes/cornell.scene > /dev/null 2>&1", binary[0] == '/' ? "" : "../", binary);
    CHECK(t, run_command(command) == 0);
    CHECK(t, file_exists("build/cornell.pfm") && file_exists("build/cornell.png"));
    CHECK(t, !file_exists("build/cornell.ppm") && !file_exists("scenes/cornell.png"));
    remove("build/cornell.pfm");
    remove("build/cornell.png");
}

/* truth: output.h: an output that is a directory is refused before any work, status 2,
 *   "is a directory", for the PNG beside -o as for -o itself; no PFM is written.
 * catches: the directory found only by the rename after the render (once status 1 and a
 *   PFM without its PNG), a temporary left behind. */
static void test_failed_png_leaves_nothing(struct check *t)
{
    remove_outputs(OUT "_dir");
    CHECK(t, run_command("mkdir -p " OUT "_dir.png") == 0);
    CHECK(t, photon("-o " OUT "_dir.png --width 4 --height 4 --spp 1 scenes/cornell.scene")
                 == 2);
    CHECK(t, log_contains(OUT "_dir.png: is a directory (the PNG beside -o)"));
    CHECK(t, no_temporaries(OUT "_dir.png") && run_command("test -d " OUT "_dir.png") == 0);
    CHECK(t, !file_exists(OUT "_dir.pfm"));
    CHECK(t, run_command("rmdir " OUT "_dir.png") == 0);
    remove_outputs(OUT "_dir");
}

void test_outputs(struct check *t)
{
    RUN_TEST(t, test_two_outputs_one_file_refused);
    RUN_TEST(t, test_output_naming_an_input_refused);
    RUN_TEST(t, test_directory_outputs_refused);
    RUN_TEST(t, test_read_only_output_refused);
    RUN_TEST(t, test_outputs_all_or_none);
    RUN_TEST(t, test_museum_exports_to_mitsuba);
    RUN_TEST(t, test_inputs_must_be_regular_files);
    RUN_TEST(t, test_nul_byte_refused);
    RUN_TEST(t, test_radiance_beyond_float_refused);
    RUN_TEST(t, test_diff_format_by_name);
    RUN_TEST(t, test_output_names);
    RUN_TEST(t, test_default_output_names);
    RUN_TEST(t, test_failed_png_leaves_nothing);
}
