/*
 * app/help.h -- photon's help, printed as text (--help all, the full list) or as the
 * manual page photon.1 (--manual, what `make install` puts in share/man/man1): one text,
 * two layouts, so the page and --help all cannot say different things (tests/test_docs.c
 * checks that they don't). --help's first screen (first_screen.h) uses the text layout.
 */
#ifndef PHOTON_HELP_H
#define PHOTON_HELP_H

enum help_format { HELP_TEXT, HELP_ROFF };

#define HELP_WIDTH 100 /* the columns a line of the text layout takes at most */

/* The page's head: nothing as text; roff's title line and NAME section. */
void help_begin(enum help_format format, const char *version);

/* A heading: as text "\nTITLE:\n" (title as given); roff a section .SH in capitals. */
void help_section(enum help_format format, const char *title);

/* Lines to keep as they stand (usage, tables); text may hold several '\n'-ended lines. */
void help_lines(enum help_format format, const char *text);

/* A row of a table whose last column is option words (a preset, --paper's): head, then
 * words, broken before an option ("--NAME", which keeps its values on its line) where the
 * line would pass HELP_WIDTH, each further line starting under the first word; kept as it
 * stands, as help_lines(). */
void help_row(enum help_format format, const char *head, const char *words);

/* One option: as text "  LEFT (padded to 26) TEXT"; roff a tagged paragraph. */
void help_option(enum help_format format, const char *left, const char *text);

/* The manual page's sections beyond --help all's (roff alone; nothing as text, which
 * stays a reference of the options): the scene format's lines, EXIT STATUS, FILES (what
 * make install puts where) and EXAMPLES. */
void help_manual_sections(enum help_format format);

#endif
