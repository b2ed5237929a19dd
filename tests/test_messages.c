/*
 * tests/test_messages.c -- what photon prints says what is so: names from a file reach
 * the terminal quoted, never as raw control bytes; numbers are echoed as typed.
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

/* truth: main.c's contract for --checkpoint: a failed checkpoint write is reported once,
 *   then no checkpoint is tried again; the final write is the run's own (reported if it
 *   fails too), and the run ends with status 1 (a write failed). Here the disk is "full"
 *   for files over 2 KiB (ulimit -f 4, as test_cli.c's test_failed_write_exits_1), so all
 *   ten checkpoints and the final image would fail: two reports, not eleven.
 * catches: the same error printed at every checkpoint (eleven lines for ten passes). */
static void test_one_failed_checkpoint_message(struct check *t)
{
    char command[1024];
    snprintf(command, sizeof command, "sh -c \"trap '' XFSZ; ulimit -f 4; %s --no-progress "
             "--mode 2008 --passes 10 --photons-per-pass 1000 --checkpoint 1 --width 64 "
             "--height 64 -o " OUT ".pfm scenes/cornell.scene\" >" OUT ".log 2>&1",
             photon_binary());
    CHECK(t, run_command(command) == 1);
    CHECK(t, log_count(OUT ".pfm: cannot write") == 2 &&
             log_count("no further checkpoint is written") == 1);
    CHECK(t, !file_exists(OUT ".pfm") && no_temporaries(OUT ".pfm"));
    run_command("rm -f " OUT "*");
}

void test_messages(struct check *t)
{
    RUN_TEST(t, test_names_are_quoted);
    RUN_TEST(t, test_numbers_echoed_as_typed);
    RUN_TEST(t, test_line_limit_as_stated);
    RUN_TEST(t, test_one_failed_checkpoint_message);
}
