/*
 * tests/test_docs.c -- the documentation against the product: tests/docs.sh checks that
 * every file the documents name exists, that every option their command lines show is one
 * photon takes, that every section cited of a mode's paper is one the paper has, and
 * that src/'s includes close no circle between modules, and runs the
 * README's commands as shown.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "files.h"
#include "tests.h"

#define LINE_MAX_BYTES 2048 /* longer than any line of --help all */

/* truth: the files in the tree, photon's own --help all, the papers' section numbers
 *   (tests/data/paper-sections.txt), and the exit status of each README
 *   command run as a user would (with --quality preview appended to renders).
 * catches: a document naming a file that was moved or never committed, an option renamed
 *   or removed under the README's feet, a command whose output directory or input is
 *   missing in a fresh clone, a banner citing a section the paper does not have (2008's
 *   "Sec. 4.4"), an include that closes a circle between modules. */
static void test_documented_commands_work(struct check *t)
{
    char command[1024];
    snprintf(command, sizeof command, "sh tests/docs.sh %s", photon_binary());
    CHECK(t, run_command(command) == 0);
}

/* The next line of *text (advanced past it) into line[LINE_MAX_BYTES], runs of spaces
 * made one and the ends trimmed; 0 at the end of the text. */
static int next_line(const char **text, char *line)
{
    if (**text == '\0')
        return 0;
    size_t n = 0;
    for (; **text != '\0' && **text != '\n'; (*text)++)
        if (n + 1 < LINE_MAX_BYTES && !(**text == ' ' && (n == 0 || line[n - 1] == ' ')))
            line[n++] = **text;
    *text += **text == '\n';
    while (n > 0 && line[n - 1] == ' ')
        n--;
    line[n] = '\0';
    return 1;
}

/* man's text back from roff as help.c writes it: "\-" "-", "\e" "\", "\&" nothing;
 * a tagged paragraph's tag and text joined on one line; other requests dropped. */
static char *unroff(const char *roff)
{
    char *text = malloc(strlen(roff) + 1), *out = text;
    int tag = 0;
    for (const char *c = roff; text != NULL && *c != '\0'; c++) {
        if ((c == roff || c[-1] == '\n') && *c == '.') {
            tag = strncmp(c, ".B ", 3) == 0;
            c += tag ? 2 : strcspn(c, "\n");
            continue;
        }
        if (*c == '\\' && (c[1] == '-' || c[1] == 'e' || c[1] == '&')) {
            c++;
            if (*c != '&')
                *out++ = *c == 'e' ? '\\' : '-';
        } else if (*c == '\n' && tag) {
            *out++ = ' ';
            tag = 0;
        } else {
            *out++ = *c;
        }
    }
    if (text != NULL)
        *out = '\0';
    return text;
}

/* --help all's text with each option's entry on one line: a line that starts with
 *   CONTINUED spaces and then a word (help.c's wrapping, under the text column) joined to
 *   the one above. */
#define CONTINUED "                             "
static void join_wrapped(char *help)
{
    char *out = help;
    for (const char *c = help; *c != '\0'; c++) {
        if (*c == '\n' && strncmp(c + 1, CONTINUED, sizeof CONTINUED - 1) == 0 &&
            c[sizeof CONTINUED] != ' ') {
            *out++ = ' ';
            c += sizeof CONTINUED - 1;
        } else {
            *out++ = *c;
        }
    }
    *out = '\0';
}

/* truth: help.h: photon.1 (--manual) is written from --help all's own text, the full
 *   list: every entry of it (a line, and the lines it is wrapped onto) but the headings
 *   (the lines from an empty line to one ending in ':') is a line of the manual page read
 *   back from its roff, the same words in the same order.
 * catches: a page written by hand or from another list of options, drifting from
 *   --help all, or from the first screen's shorter one; an option's text escaped so that
 *   man shows something else. */
static void test_manual_is_the_help(struct check *t)
{
    char help_log[256], manual_log[256], line[LINE_MAX_BYTES], *manual = NULL;
    temp_name(help_log, sizeof help_log, "docs", "help.txt");
    temp_name(manual_log, sizeof manual_log, "docs", "photon.1");
    REQUIRE(t, photon_logged("--help", "all", help_log) == 0);
    REQUIRE(t, photon_logged("--manual", "", manual_log) == 0);
    char *help = read_text_file(help_log), *roff = read_text_file(manual_log);
    if (help != NULL)
        join_wrapped(help);
    manual = roff != NULL ? unroff(roff) : NULL;
    int heading = 0, lines = 0;
    for (const char *h = help; h != NULL && manual != NULL && next_line(&h, line);) {
        if (line[0] == '\0') {
            heading = 1;
            continue;
        }
        if (!heading) {
            int found = 0;
            char other[LINE_MAX_BYTES];
            for (const char *m = manual; !found && next_line(&m, other);)
                found = strcmp(line, other) == 0;
            CHECK(t, found);
            if (!found)
                fprintf(stderr, "test_docs: not in photon.1: %s\n", line);
            lines++;
        }
        heading = heading && line[strlen(line) - 1] != ':';
    }
    CHECK(t, lines > 100 && roff != NULL && strncmp(roff, ".TH PHOTON 1", 12) == 0);
    free(manual);
    free(roff);
    free(help);
    remove(help_log);
    remove(manual_log);
}

/* Whether --help's text has an entry for option (a line "  OPTION ..."). */
static int has_entry(const char *help, const char *option)
{
    char start[64];
    snprintf(start, sizeof start, "\n  %s ", option);
    return strstr(help, start) != NULL;
}

/* truth: the README's modes table and src/modes/README.md: --passes and
 *   --disc-coverage belong to 2009, --gather-rays to 1994 and 1996, --spp not to 2009
 *   (its passes are its samples); photon --help 2009 lists that mode's options alone, and
 *   its --paper words (test_help.c keeps every page within 100 columns).
 * catches: --help MODE read as a scene or ignored; another mode's options listed. */
static void test_help_of_a_mode(struct check *t)
{
    char log[256];
    temp_name(log, sizeof log, "docs", "help_mode.txt");
    REQUIRE(t, photon_logged("--help", "2009", log) == 0);
    char *help = read_text_file(log);
    REQUIRE(t, help != NULL);
    CHECK(t, has_entry(help, "--passes") && has_entry(help, "--disc-coverage") &&
             has_entry(help, "--no-turn-photon-directions") && !has_entry(help, "--gather-rays") &&
             !has_entry(help, "--spp") && has_entry(help, "--mode 2009") &&
             !has_entry(help, "--mode 1996"));
    free(help);
    remove(log);
}

/* photon --manual's text (NULL when it fails), its temporary file removed. */
static char *manual_text(void)
{
    char log[256];
    temp_name(log, sizeof log, "docs", "manual.1");
    char *roff = photon_logged("--manual", "", log) == 0 ? read_text_file(log) : NULL;
    remove(log);
    return roff;
}

/* Whether text is in roff's section `section`, before the section `next` begins. */
static int in_section(const char *roff, const char *section, const char *next,
                      const char *text)
{
    const char *from = strstr(roff, section), *to = strstr(roff, next);
    const char *at = from != NULL ? strstr(from, text) : NULL;
    return at != NULL && to != NULL && at < to;
}

/* truth: README.md's table of scene lines (its first column's keywords, read here from
 *   the README itself) and the manual's usual sections: the page has SCENE FILES naming
 *   every keyword the README's table does, and EXIT STATUS (0, 1, 2), FILES and EXAMPLES.
 * catches: a scene keyword added to the README and the parser but not to the page; a
 *   section dropped. */
static void test_manual_sections(struct check *t)
{
    char *roff = manual_text(), *readme = read_text_file("README.md");
    REQUIRE(t, roff != NULL && readme != NULL);
    CHECK(t, strstr(roff, ".SH SCENE FILES") && strstr(roff, ".SH EXIT STATUS") &&
             strstr(roff, ".SH FILES") && strstr(roff, ".SH EXAMPLES"));
    const char *table = strstr(readme, "| `image W H`");
    int keywords = 0;
    for (const char *row = table; row != NULL && strncmp(row, "| `", 3) == 0;
         row = strchr(row, '\n') != NULL ? strchr(row, '\n') + 1 : NULL) {
        char keyword[32];
        if (sscanf(row + 3, "%31[a-z_]", keyword) != 1)
            continue;
        int found = in_section(roff, ".SH SCENE FILES", ".SH EXIT", keyword);
        CHECK(t, found);
        if (!found)
            fprintf(stderr, "test_docs: the manual's scene files lack %s\n", keyword);
        keywords++;
    }
    CHECK(t, keywords >= 15);
    free(roff);
    free(readme);
}

/* truth: error.h: a command whose write of the standard output fails says why and exits
 *   1, as a failed write of a file does; the manual's EXIT STATUS and the README's Errors
 *   paragraph (read with its line breaks as spaces) say so.
 * catches: documents that leave a failed stdout to "a write that failed after the work",
 *   which a reader takes for a file (photon --manual > photon.1 on a full disk). */
static void test_exit_status_of_stdout(struct check *t)
{
    char *roff = manual_text(), *readme = read_text_file("README.md");
    REQUIRE(t, roff != NULL && readme != NULL);
    CHECK(t, in_section(roff, ".SH EXIT STATUS", ".SH FILES", "the standard output's too"));
    for (char *c = readme; *c != '\0'; c++)
        *c = *c == '\n' ? ' ' : *c;
    CHECK(t, strstr(readme, "a failed write, of stdout too) says why and exits with status "
                            "1") != NULL);
    free(roff);
    free(readme);
}

void test_docs(struct check *t)
{
    RUN_TEST(t, test_documented_commands_work);
    RUN_TEST(t, test_manual_is_the_help);
    RUN_TEST(t, test_help_of_a_mode);
    RUN_TEST(t, test_manual_sections);
    RUN_TEST(t, test_exit_status_of_stdout);
}
