/*
 * tests/test_messages.c -- what photon prints says what is so: names from a file reach
 * the terminal quoted, never as raw control bytes; numbers are echoed as typed; a failed
 * write or read says why (errno), once, of the file the user named; a load says "load";
 * and the README's limits (a line's bytes, a name's) are what photon does.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "tests.h"

#define OUT "build/test_messages"

/* Whether the log holds no byte outside printable ASCII but newlines (and \r of the
 * progress line, which --no-progress turns off). */
static int log_is_printable(void)
{
    char *text = read_text_file(OUT ".log");
    int printable = text != NULL;
    for (const unsigned char *c = (const unsigned char *)text; printable && *c != '\0'; c++)
        printable = (*c >= 0x20 && *c < 0x7f) || *c == '\n';
    free(text);
    return printable;
}

/* truth: error.h's rule, now for warnings and notes too: a byte of a name outside
 *   printable ASCII is printed as \xNN. The material's name below holds ESC [31m (red
 *   text on a terminal) and BEL; 2008's glossy warning and export's note on Phong name
 *   it, and so does the no-light warning the scene's own path.
 * catches: the 2008 warning and export's notes printing ESC and BEL raw (the issue's
 *   case), so that a scene file could colour or ring the user's terminal. */
static void test_names_are_quoted(struct check *t)
{
    write_text_file(OUT ".scene", "camera 0 0 -3 0 0 0 0 1 0 40\n"
                    "material m\x1b[31m\x07 phong 0.4 0.4 0.4 0.3 0.3 0.3 20\n"
                    "sphere 0 0 0 1 m\x1b[31m\x07\nlight point 0 2 -2 10 10 10\n");
    CHECK(t, photon_logged("", "--no-progress --mode 2008 --passes 1 --photons-per-pass 100 "
                           "--spp 1 --width 2 --height 2 -o " OUT ".pfm " OUT ".scene",
                           OUT ".log") == 0);
    CHECK(t, file_contains(OUT ".log", "material 'm\\x1b[31m\\x07')") && log_is_printable());
    CHECK(t, photon_logged("export", "--format pbrt " OUT ".scene -o " OUT ".pbrt",
                           OUT ".log") == 0);
    CHECK(t, file_contains(OUT ".log", "material \"m\\x1b[31m\\x07\"") && log_is_printable());
    write_text_file(OUT "\x1b[1m.scene", "camera 0 0 -3 0 0 0 0 1 0 40\n"
                    "material m lambert 0.5 0.5 0.5\nsphere 0 0 0 1 m\n");
    CHECK(t, photon_logged("", "--no-progress --width 2 --height 2 -o " OUT ".pfm '"
                           OUT "\x1b[1m.scene'", OUT ".log") == 0);
    CHECK(t, file_contains(OUT ".log", OUT "\\x1b[1m.scene has no light") &&
             log_is_printable());
    run_command("rm -f " OUT "*");
}

#define NFF_VIEW "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 6\n" \
                 "f 1 1 1 1 0 0 0 0\n"

/* truth: the words of each file below, as typed: a value out of its range is echoed as
 *   the user wrote it, not as printf's %g makes it again (1e+20, 1000, -0.5, 7).
 * catches: messages that print the parsed double, which then names a number the file
 *   does not hold. */
static void test_numbers_echoed_as_typed(struct check *t)
{
    static const char *const cases[][3] = {
        {".scene", "camera 0 0 -3 0 0 0 0 1 0 40\nimage 8 99999999999999999999\n",
         "got 99999999999999999999"},
        {".nff", "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 1e3\nhither 1\n", "got 1e3"},
        {".nff", "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\n"
                 "resolution 8 0040000\n", "got 0040000"},
        {".nff", NFF_VIEW "s 0 0 0 -0.50\n", "got -0.50"},
        {".nff", NFF_VIEW "p 02\n", "got 02"},
        {".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 007\n", "vertex index 007 is out"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char name[64], args[256];
        snprintf(name, sizeof name, OUT "%s", cases[i][0]);
        write_text_file(name, cases[i][1]);
        if (strcmp(cases[i][0], ".obj") == 0) {
            write_text_file(OUT ".scene", "camera 0 0 -3 0 0 0 0 1 0 40\nmaterial m lambert "
                            "0.5 0.5 0.5\nobj test_messages.obj m\n");
            snprintf(name, sizeof name, OUT ".scene");
        }
        snprintf(args, sizeof args, "--no-progress -o " OUT ".pfm %s", name);
        int right = photon_logged("", args, OUT ".log") == 2 &&
                    file_contains(OUT ".log", cases[i][2]);
        CHECK(t, right);
        if (!right)
            fprintf(stderr, "test_messages: case %zu: no '%s'\n", i, cases[i][2]);
    }
    run_command("rm -f " OUT "*");
}

/* Writes a scene whose second line is a comment of `bytes` bytes, its newline included. */
static void write_long_line_scene(size_t bytes)
{
    char *text = malloc(bytes + 128);
    if (text == NULL)
        return;
    size_t n = (size_t)sprintf(text, "camera 0 0 -3 0 0 0 0 1 0 40\n#");
    memset(text + n, 'x', bytes - 2);
    n += bytes - 2;
    sprintf(text + n, "\nmaterial m lambert 0.5 0.5 0.5\nsphere 0 0 0 1 m\n");
    write_text_file(OUT ".scene", text);
    free(text);
}

/* truth: the README's limit, "4096 bytes a line", and scene/parser.h's MAX_LINE, "the
 *   newline included": a line of 4096 bytes is read, one of 4097 refused, the message
 *   naming the limit the README states.
 * catches: a 4095-byte line refused as "longer than 4094" (input_line's buffer held one
 *   byte less than it said, and the message another one less). */
static void test_line_limit_as_stated(struct check *t)
{
    write_long_line_scene(4096);
    CHECK(t, photon_logged("", "--no-progress --width 2 --height 2 -o " OUT ".pfm " OUT
                           ".scene", OUT ".log") == 0);
    write_long_line_scene(4097);
    CHECK(t, photon_logged("", "--no-progress --width 2 --height 2 -o " OUT ".pfm " OUT
                           ".scene", OUT ".log") == 2 &&
             file_contains(OUT ".log", OUT ".scene:2: line longer than 4096 bytes, its "
                           "newline included"));
    run_command("rm -f " OUT "*");
}

/* How many times text occurs in the log. */
static int log_count(const char *text)
{
    char *log = read_text_file(OUT ".log");
    int n = 0;
    for (const char *p = log != NULL ? strstr(log, text) : NULL; p != NULL;
         p = strstr(p + 1, text))
        n++;
    free(log);
    return n;
}

/* Runs "PHOTON args" in a shell whose files may not grow past 2 KiB (ulimit -f 4, in
 * 512-byte blocks, as test_cli.c's test_failed_write_exits_1; SIGXFSZ ignored, so a
 * longer write fails with EFBIG as on a full disk, after the outputs' check, whose probes
 * are a line each), its output in OUT.log; the exit status. */
static int photon_small_files(const char *args)
{
    char command[2048];
    snprintf(command, sizeof command, "sh -c \"trap '' XFSZ; ulimit -f 4; %s %s\" >" OUT
             ".log 2>&1", photon_binary(), args);
    return run_command(command);
}

/* truth: main.c's contract for --checkpoint: a failed checkpoint write is reported once,
 *   then no checkpoint is tried again; the final write is the run's own (reported if it
 *   fails too), and the run ends with status 1 (a write failed). Here the disk is "full"
 *   for files over 2 KiB (photon_small_files()), so all ten checkpoints and the final
 *   image would fail: two reports, not eleven, each with its reason.
 * catches: the same error printed at every checkpoint (eleven lines for ten passes). */
static void test_one_failed_checkpoint_message(struct check *t)
{
    CHECK(t, photon_small_files("--no-progress --mode 2008 --passes 10 --photons-per-pass "
                                "1000 --checkpoint 1 --width 64 --height 64 -o " OUT ".pfm "
                                "scenes/cornell.scene") == 1);
    CHECK(t, log_count(OUT ".pfm: cannot write output file: File too large\n") == 2 &&
             log_count("no further checkpoint is written") == 1);
    CHECK(t, !file_exists(OUT ".pfm") && no_temporaries(OUT ".pfm"));
    run_command("rm -f " OUT "*");
}

/* truth: output.h: a write that fails says why, once, naming the file the user asked
 *   for, never its temporary, and the run exits 1: here files may not grow past 2 KiB
 *   (photon_small_files()), so one large output of each command fails with EFBIG,
 *   strerror()'s "File too large" (the render's PFM and its --save-photons, merge's,
 *   convert's and compare --diff's pictures, export's scene, probe's CSV, plot's SVG:
 *   every writer reaches output_commit()). Nothing is left of it. The render's OpenEXR
 *   (3.3 KB) sits in stdio's buffer until the seek back to its offset table flushes it:
 *   there the write fails.
 * catches: "cannot write output file" alone: stdio keeps that a write failed (ferror()),
 *   not why, and errno has changed by the commit; the reason printed twice; a message
 *   naming NAME.XXXXXXXX.tmp; the OpenEXR's failed seek said without why ("cannot go
 *   back to the offset table to write it"). */
static void test_failed_write_says_why(struct check *t)
{
    static const char *const cases[][2] = {
        {"--no-progress --spp 1 --width 64 --height 64 -o " OUT "_r.pfm scenes/cornell.scene",
         OUT "_r.pfm"},
        {"--no-progress --spp 1 --width 16 --height 16 -o " OUT "_x.exr scenes/cornell.scene",
         OUT "_x.exr"},
        {"--no-progress --mode photons --photons 20000 --width 4 --height 4 --save-photons "
         OUT "_w.work -o " OUT "_w.pfm scenes/cornell.scene", OUT "_w.work"},
        {"merge -o " OUT "_m.pfm " OUT "_t.pfm", OUT "_m.pfm"},
        {"convert " OUT "_a.pfm -o " OUT "_c.ppm", OUT "_c.ppm"},
        {"compare " OUT "_a.pfm " OUT "_t.pfm --diff " OUT "_d.ppm", OUT "_d.ppm"},
        {"export --format pbrt scenes/ppm-box.scene -o " OUT "_e.pbrt", OUT "_e.pbrt"},
        {"export --format blender scenes/cornell.scene -o " OUT "_b.py", OUT "_b.py"},
        {"probe scenes/cornell.scene --line 0 0 0 1 1 1 --samples 100 --photons 2000 -o " OUT
         "_q.csv", OUT "_q.csv"},
        {"plot --linear --x x --y all_photons " OUT "_p.csv -o " OUT "_s.svg", OUT "_s.svg"},
    };
    CHECK(t, photon_logged("", "--no-progress --spp 1 --width 64 --height 64 -o " OUT "_a.pfm "
                           "scenes/cornell.scene", OUT ".log") == 0);
    CHECK(t, photon_logged("", "--no-progress --spp 1 --seed 2 --width 64 --height 64 --crop "
                           "0 0 64 64 -o " OUT "_t.pfm scenes/cornell.scene", OUT ".log") == 0);
    CHECK(t, photon_logged("probe", "scenes/cornell.scene --line 0 0 0 1 1 1 --samples 100 "
                           "--photons 2000 -o " OUT "_p.csv", OUT ".log") == 0);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char expected[256];
        snprintf(expected, sizeof expected, "%s: cannot write output file: File too large\n",
                 cases[i][1]);
        int right = photon_small_files(cases[i][0]) == 1 && log_count(expected) == 1 &&
                    log_count("File too large") == 1 && log_count(".tmp") == 0 &&
                    !file_exists(cases[i][1]) && no_temporaries(cases[i][1]);
        CHECK(t, right);
        if (!right)
            fprintf(stderr, "test_messages: no single '%s'\n", expected);
    }
    run_command("rm -f " OUT "*");
}

/* truth: error.h: what a command prints on its standard output is written, or the run
 *   says it was not and exits 1: --help, --manual and compare's line sent to /dev/full,
 *   where every write fails with ENOSPC ("No space left on device"). Skipped where there
 *   is no /dev/full.
 * catches: status 0 with nothing written (photon --manual > photon.1 on a full disk left
 *   an empty manual page, and make install went on). */
static void test_standard_output_failure(struct check *t)
{
    static const char *const commands[] = {"--help", "--manual", "compare " OUT "_a.pfm " OUT
                                           "_a.pfm"};
    if (run_command("test -c /dev/full") != 0) {
        printf("  (test_standard_output_failure: no /dev/full, skipped)\n");
        return;
    }
    CHECK(t, photon_logged("", "--no-progress --spp 1 --width 4 --height 4 -o " OUT "_a.pfm "
                           "scenes/cornell.scene", OUT ".log") == 0);
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        char command[1024];
        snprintf(command, sizeof command, "%s %s >/dev/full 2>" OUT ".log", photon_binary(),
                 commands[i]);
        CHECK(t, run_command(command) == 1 &&
                 log_count("photon: cannot write the standard output: No space left on "
                           "device\n") == 1);
    }
    run_command("rm -f " OUT "*");
}

/* truth: work_file.h: --load-photons loads its file, and every refusal of it says so,
 *   naming the file and the option: one that is missing, one that is no saved work.
 * catches: a bare "cannot open" or "not a file of photon's saved global work" that does
 *   not say the file was being loaded, nor for which option. */
static void test_load_says_load(struct check *t)
{
    static const char *const cases[][2] = {
        {OUT "_none.work", OUT "_none.work: cannot load the saved work (--load-photons): "
                           "cannot open: No such file"},
        {OUT "_junk.work", OUT "_junk.work: cannot load the saved work (--load-photons): "
                           "not a file of photon's saved global work"},
    };
    write_text_file(OUT "_junk.work", "junk\n");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char args[512];
        snprintf(args, sizeof args, "--no-progress --mode photons --photons 2000 --width 4 "
                 "--height 4 --load-photons %s -o " OUT ".pfm scenes/cornell.scene",
                 cases[i][0]);
        CHECK(t, photon_logged("", args, OUT ".log") == 2 && file_contains(OUT ".log",
                                                                         cases[i][1]));
    }
    run_command("rm -f " OUT "*");
}

/* truth: input.h: a file that opens but cannot be read is refused with the reason the
 *   read gave (errno): /proc/self/clear_refs, which the kernel opens and does not read
 *   ("Invalid argument"; "Permission denied" at the open for a user other than root).
 *   Skipped where there is no such file.
 * catches: "cannot be read (is it a directory?)", a guess that was wrong once input_open()
 *   refused directories before reading. */
static void test_read_failure_says_why(struct check *t)
{
    if (run_command("test -e /proc/self/clear_refs") != 0) {
        printf("  (test_read_failure_says_why: no /proc/self/clear_refs, skipped)\n");
        return;
    }
    CHECK(t, photon_logged("compare", "/proc/self/clear_refs scenes/cornell.scene", OUT
                           ".log") == 2 && file_contains(OUT ".log", "/proc/self/clear_refs: "
                           "cannot ") && !file_contains(OUT ".log", "directory"));
    run_command("rm -f " OUT "*");
}

/* A name in build/ whose last part is 255 bytes: test_messages_, x's, then end. */
static void long_name(char *name, const char *end)
{
    size_t n = (size_t)sprintf(name, OUT "_");
    size_t x = 255 - strlen("test_messages_") - strlen(end);
    memset(name + n, 'x', x);
    strcpy(name + n + x, end);
}

/* truth: temporary_name.h: an output's name may be as long as its file system takes (255
 *   bytes on most), though NAME.XXXXXXXX.tmp adds 13: the names of ours of a long name
 *   are cut and keep a hash of it. So -o and --variance of 255 bytes, alike but for their
 *   last bytes, are written, two files; the same file spelt again (./build/...) is still
 *   refused as one.
 * catches: a 255-byte -o refused as "File name too long" (its temporary's 268 bytes), the
 *   README's limits (a line, a name) not what photon does; two long names cut to one
 *   temporary name and taken for one file. */
static void test_long_output_name(struct check *t)
{
    char pfm[300], variance[300], args[1024];
    long_name(pfm, ".pfm");
    long_name(variance, "v.pfm");
    snprintf(args, sizeof args, "--no-progress --spp 2 --width 2 --height 2 -o %s --variance "
             "%s scenes/cornell.scene", pfm, variance);
    CHECK(t, photon_logged("", args, OUT ".log") == 0 && file_exists(pfm) &&
             file_exists(variance) && no_temporaries(pfm) && no_temporaries(variance));
    snprintf(args, sizeof args, "--no-progress --spp 2 --width 2 --height 2 -o %s --variance "
             "./%s scenes/cornell.scene", pfm, pfm);
    CHECK(t, photon_logged("", args, OUT ".log") == 2 &&
             file_contains(OUT ".log", "--variance names the same file as -o"));
    run_command("rm -f " OUT "*");
}

void test_messages(struct check *t)
{
    RUN_TEST(t, test_names_are_quoted);
    RUN_TEST(t, test_numbers_echoed_as_typed);
    RUN_TEST(t, test_line_limit_as_stated);
    RUN_TEST(t, test_one_failed_checkpoint_message);
    RUN_TEST(t, test_failed_write_says_why);
    RUN_TEST(t, test_standard_output_failure);
    RUN_TEST(t, test_load_says_load);
    RUN_TEST(t, test_read_failure_says_why);
    RUN_TEST(t, test_long_output_name);
}
