/*
 * tests/test_help.c -- the help room: `photon --help`'s first screen fits a terminal and
 * names what the program has, `photon --help all` lists every option, and every command
 * answers --help. The modes, commands and options are read from the program's own tables
 * (option_values.h's every_mode, commands.h, option_table.h), not from a copy here, so a
 * mode, command or option added later is checked too; every page of --help keeps within
 * 100 columns.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/app/commands.h"
#include "../src/app/first_screen.h"
#include "../src/app/option_table.h"
#include "../src/app/option_values.h"
#include "check.h"
#include "files.h"
#include "tests.h"

#define NAME_BYTES 256
#define COMMAND_BYTES 1024
#define SCREEN_COLUMNS 100

/* Runs "PHOTON words" with stdout alone into out (stderr into err): its exit status. */
static int photon_stdout(const char *words, const char *out, const char *err)
{
    char command[COMMAND_BYTES];
    snprintf(command, sizeof command, "%s %s >%s 2>%s", photon_binary(), words, out, err);
    return run_command(command);
}

/* Whether text has an entry for name: a line "  NAME " (help.c's text layout). */
static int has_entry(const char *text, const char *name)
{
    char start[96];
    snprintf(start, sizeof start, "\n  %s ", name);
    return strstr(text, start) != NULL;
}

/* The number of lines of text, and in *widest the longest one's columns (bytes: the help
 * is ASCII). */
static int count_lines(const char *text, size_t *widest)
{
    int lines = 0;
    *widest = 0;
    for (const char *c = text; *c != '\0'; lines++) {
        size_t n = strcspn(c, "\n");
        *widest = n > *widest ? n : *widest;
        c += n + (c[n] == '\n');
    }
    return lines;
}

/* truth: first_screen.h: photon --help (and -h) prints at most FIRST_SCREEN_LINES (40)
 *   lines of at most 100 columns, exit status 0 and nothing on stderr; an entry for every
 *   mode of the parser's list and every command main.c runs, and the ways to the rest:
 *   --help MODE, --help all, COMMAND --help. A word after --help that is neither all nor a
 *   mode (a scene) gives the same screen.
 * catches: the 255-line list back as the first screen; a mode or command added to the
 *   program but not to the screen; a summary that wraps or runs past 100 columns. */
static void test_first_screen(struct check *t)
{
    char out[NAME_BYTES], err[NAME_BYTES], again[NAME_BYTES];
    temp_name(out, sizeof out, "help", "first.txt");
    temp_name(err, sizeof err, "help", "first.err");
    temp_name(again, sizeof again, "help", "again.txt");
    REQUIRE(t, photon_stdout("--help", out, err) == 0);
    char *screen = read_text_file(out), *errors = read_text_file(err);
    REQUIRE(t, screen != NULL && errors != NULL);
    size_t widest;
    int lines = count_lines(screen, &widest);
    CHECK(t, lines >= 20 && lines <= FIRST_SCREEN_LINES && widest <= SCREEN_COLUMNS);
    if (lines > FIRST_SCREEN_LINES || widest > SCREEN_COLUMNS)
        fprintf(stderr, "test_help: the first screen is %d lines, %zu columns wide\n", lines,
                widest);
    CHECK(t, errors[0] == '\0' && strncmp(screen, "usage: photon ", 14) == 0);
    for (size_t m = 0; m < N_EVERY_MODE; m++)
        CHECK(t, has_entry(screen, mode_name(every_mode[m])));
    for (size_t i = 0; i < N_COMMANDS; i++)
        CHECK(t, has_entry(screen, commands[i].name));
    CHECK(t, strstr(screen, "photon --help MODE") && strstr(screen, "photon --help all") &&
             strstr(screen, "photon COMMAND --help"));
    CHECK(t, photon_stdout("-h", again, err) == 0 && files_equal(out, again));
    CHECK(t, photon_stdout("--help scenes/cornell.scene", again, err) == 0 &&
             files_equal(out, again));
    free(screen);
    free(errors);
    remove(out);
    remove(err);
    remove(again);
}

/* truth: the option table (option_table.c): photon --help all, the full list the manual
 *   page is written from, has an entry for every row, and for --help, --version and
 *   --manual; it is longer than the first screen, which it does not replace.
 * catches: an option the parser takes that the full list leaves out; --help all read as
 *   a mode or a scene. */
static void test_help_all_lists_every_option(struct check *t)
{
    char out[NAME_BYTES], err[NAME_BYTES];
    temp_name(out, sizeof out, "help", "all.txt");
    temp_name(err, sizeof err, "help", "all.err");
    REQUIRE(t, photon_stdout("--help all", out, err) == 0);
    char *all = read_text_file(out);
    REQUIRE(t, all != NULL);
    for (size_t i = 0; i < N_OPTION_SPECS; i++) {
        int listed = has_entry(all, option_specs[i].name);
        CHECK(t, listed);
        if (!listed)
            fprintf(stderr, "test_help: --help all lists no %s\n", option_specs[i].name);
    }
    CHECK(t, has_entry(all, "--help") && has_entry(all, "--version") &&
             has_entry(all, "--manual"));
    size_t widest;
    CHECK(t, count_lines(all, &widest) > 2 * FIRST_SCREEN_LINES);
    free(all);
    remove(out);
    remove(err);
}

/* truth: --help is a question, not bad input (status 2, README: Errors and determinism):
 *   every command of main.c's table (commands.h) answers `photon COMMAND --help` with its
 *   usage on stdout and exit status 0.
 * catches: a command added without --help, or whose --help exits 1 or 2 (read as a bad
 *   option), or prints to stderr alone. */
static void test_every_command_answers_help(struct check *t)
{
    char out[NAME_BYTES], err[NAME_BYTES], words[64], usage[64];
    temp_name(out, sizeof out, "help", "command.txt");
    temp_name(err, sizeof err, "help", "command.err");
    for (size_t i = 0; i < N_COMMANDS; i++) {
        snprintf(words, sizeof words, "%s --help", commands[i].name);
        snprintf(usage, sizeof usage, "photon %s", commands[i].name);
        int status = photon_stdout(words, out, err);
        CHECK(t, status == 0 && file_contains(out, usage));
        if (status != 0)
            fprintf(stderr, "test_help: photon %s: exit status %d\n", words, status);
    }
    remove(out);
    remove(err);
}

/* Checks that no line of "PHOTON words"'s output passes SCREEN_COLUMNS, naming the page
 * and its widest line where one does. */
static void check_page_fits(struct check *t, const char *words, const char *out,
                            const char *err)
{
    CHECK(t, photon_stdout(words, out, err) == 0);
    char *page = read_text_file(out);
    REQUIRE(t, page != NULL);
    size_t widest;
    int lines = count_lines(page, &widest);
    CHECK(t, lines > 0 && widest <= SCREEN_COLUMNS);
    if (widest > SCREEN_COLUMNS)
        fprintf(stderr, "test_help: photon %s: a line of %zu columns\n", words, widest);
    free(page);
}

/* truth: help.h's HELP_WIDTH, the terminal the help is written for: every page of help
 *   (photon --help, --help all, --help MODE for each mode, COMMAND --help for each
 *   command) keeps each line within 100 columns: a preset's or --paper's words, wrapped,
 *   go on under their first word, and a command's usage runs on over several lines.
 * catches: a row of option words added or grown past the edge (--help all's 1996 --paper
 *   row was 214 columns); a command's usage printed on one line (compare's was 281). */
static void test_every_page_fits(struct check *t)
{
    char out[NAME_BYTES], err[NAME_BYTES], words[64];
    temp_name(out, sizeof out, "help", "page.txt");
    temp_name(err, sizeof err, "help", "page.err");
    check_page_fits(t, "--help", out, err);
    check_page_fits(t, "--help all", out, err);
    for (size_t m = 0; m < N_EVERY_MODE; m++) {
        snprintf(words, sizeof words, "--help %s", mode_name(every_mode[m]));
        check_page_fits(t, words, out, err);
    }
    for (size_t i = 0; i < N_COMMANDS; i++) {
        snprintf(words, sizeof words, "%s --help", commands[i].name);
        check_page_fits(t, words, out, err);
    }
    remove(out);
    remove(err);
}

void test_help(struct check *t)
{
    RUN_TEST(t, test_first_screen);
    RUN_TEST(t, test_help_all_lists_every_option);
    RUN_TEST(t, test_every_command_answers_help);
    RUN_TEST(t, test_every_page_fits);
}
