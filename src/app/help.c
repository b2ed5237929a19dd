/*
 * app/help.c -- the two layouts of photon's help (help.h).
 *
 * roff (man(7)): every '-' is written "\-" (a minus, so that an option can be searched and
 * copied), every '\' as "\e", and a line that would start with '.' or '\'' gets "\&"
 * before it, so no text of ours is read as a request.
 */
#include "help.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

/* text as roff body text, from the start of a line. */
static void put_roff(const char *text)
{
    int line_start = 1;
    for (const char *c = text; *c != '\0'; c++) {
        if (line_start && (*c == '.' || *c == '\''))
            fputs("\\&", stdout);
        if (*c == '-')
            fputs("\\-", stdout);
        else if (*c == '\\')
            fputs("\\e", stdout);
        else
            putchar(*c);
        line_start = *c == '\n';
    }
}

void help_begin(enum help_format format, const char *version)
{
    if (format == HELP_TEXT)
        return;
    printf(".TH PHOTON 1 \"\" \"photon %s\" \"User Commands\"\n.SH NAME\n", version);
    put_roff("photon - a reference implementation of photon mapping (Jensen 1994, 1996; "
             "Hachisuka 2008, 2009) and a path tracer\n");
}

void help_section(enum help_format format, const char *title)
{
    if (format == HELP_TEXT) {
        printf("\n%s:\n", title);
        return;
    }
    /* The words before a parenthesis head the section; the parenthesis is its text. */
    const char *note = strstr(title, " (");
    size_t n = note != NULL ? (size_t)(note - title) : strlen(title);
    fputs(".SH ", stdout);
    for (size_t i = 0; i < n; i++) {
        if (title[i] == '-')
            fputs("\\-", stdout);
        else
            putchar(toupper((unsigned char)title[i]));
    }
    putchar('\n');
    if (note != NULL) {
        put_roff(note + 1);
        putchar('\n');
    }
}

void help_lines(enum help_format format, const char *text)
{
    if (format == HELP_TEXT) {
        fputs(text, stdout);
        return;
    }
    fputs(".nf\n", stdout);
    put_roff(text);
    fputs(".fi\n", stdout);
}

#define HELP_WIDTH 100      /* the columns a line of the text layout takes at most  */
#define HELP_TEXT_COLUMN 29 /* where an option's text starts: 2 + 26 + a space       */

/* text from column HELP_TEXT_COLUMN on, broken at spaces so that no line passes
 * HELP_WIDTH (a word longer than the room stands alone on its line). */
static void put_wrapped(const char *text)
{
    const size_t room = HELP_WIDTH - HELP_TEXT_COLUMN;
    while (*text != '\0') {
        size_t cut = strlen(text);
        if (cut > room) {
            cut = room;
            while (cut > 0 && text[cut] != ' ')
                cut--;
            if (cut == 0)
                cut = strcspn(text, " ");
        }
        printf("%.*s\n", (int)cut, text);
        text += cut;
        while (*text == ' ')
            text++;
        if (*text != '\0')
            printf("%*s", HELP_TEXT_COLUMN, "");
    }
}

void help_option(enum help_format format, const char *left, const char *text)
{
    if (format == HELP_TEXT) {
        if (strlen(left) <= HELP_TEXT_COLUMN - 3)
            printf("  %-26s ", left);
        else
            printf("  %s\n%*s", left, HELP_TEXT_COLUMN, "");
        put_wrapped(text);
        return;
    }
    fputs(".TP\n.B ", stdout);
    put_roff(left);
    putchar('\n');
    put_roff(text);
    putchar('\n');
}
