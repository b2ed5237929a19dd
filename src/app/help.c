/*
 * app/help.c -- the two layouts of photon's help (help.h).
 *
 * roff (man(7)): every '-' is written "\-" (a minus, so that an option can be searched and
 * copied), every '\' as "\e", and a line that would start with '.' or '\'' gets "\&"
 * before it, so no text of ours is read as a request.
 */
#include "help.h"

#include <assert.h>
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

void help_row(enum help_format format, const char *head, const char *words)
{
    char text[1024];
    size_t indent = strlen(head), used = 0, line = 0;
    assert(indent + strlen(words) < sizeof text / 2); /* room for the breaks' indents */
    used += (size_t)sprintf(text, "%s", head);
    while (*words != '\0') {
        /* The next option and its values: up to the next " --", or the end. */
        const char *next = strstr(words + 1, " --");
        size_t n = next != NULL ? (size_t)(next - words) : strlen(words);
        if (used - line > indent && used - line + 1 + n > HELP_WIDTH) {
            used += (size_t)sprintf(text + used, "\n%*s", (int)indent, "");
            line = used - indent;
        } else if (used - line > indent) {
            text[used++] = ' ';
        }
        used += (size_t)sprintf(text + used, "%.*s", (int)n, words);
        words += n + (next != NULL);
    }
    sprintf(text + used, "\n");
    help_lines(format, text);
}

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

/* One line of a scene file each: its words, and what it makes (README.md: Scene files). */
static const char *const scene_lines[][2] = {
    {"image W H", "the image size in pixels (default 256 x 256)"},
    {"camera FROM AT UP FOV [aperture R focus D]",
     "a pinhole or thin-lens camera; FOV the full vertical field of view in degrees"},
    {"background R G B", "the radiance of rays that leave the scene: a sky that lights it"},
    {"material NAME lambert|mirror|glass|phong|ward|schlick ...",
     "a material (README.md lists each model's parameters)"},
    {"sphere X Y Z R MATERIAL", "a sphere"},
    {"triangle V0 V1 V2 MATERIAL", "a triangle (smooth_triangle adds three normals)"},
    {"quad P0 P1 P2 P3 MATERIAL", "a parallelogram by its corners in order"},
    {"light point X Y Z R G B", "a point light of power R G B watts"},
    {"light sphere|quad ...", "an area light by the radiance it emits"},
    {"sphereflake ...", "Haines' sphere flake"},
    {"heightfield ...", "a fractal heightfield"},
    {"nff FILE, obj FILE MATERIAL ...", "an NFF scene, or an OBJ mesh (rotate, scale and "
                                        "translate it; usemtl names scene materials), read "
                                        "in place"},
    {"include FILE", "another scene file read in place"},
};

void help_manual_sections(enum help_format format)
{
    if (format != HELP_ROFF)
        return;
    help_section(format, "scene files (a line each, '#' a comment; README.md: Scene files)");
    for (size_t i = 0; i < sizeof scene_lines / sizeof scene_lines[0]; i++)
        help_option(format, scene_lines[i][0], scene_lines[i][1]);
    help_section(format, "exit status");
    help_option(format, "0", "the command did its work and wrote its outputs");
    help_option(format, "1", "a machine failure (out of memory, a write that failed after "
                             "the work, the standard output's too), said with its reason; no "
                             "partial output file is left");
    help_option(format, "2", "bad input (an option, a scene, an image file): "
                             "file:line: message on stderr, nothing written");
    help_option(format, "128 + N", "signal N ended photon, after it undid its files");
    help_section(format, "files");
    help_option(format, "PREFIX/share/photon", "the shipped scenes, where make install puts "
                                               "them (PREFIX /usr/local by default)");
    help_option(format, "NAME.pfm, NAME.exr, NAME.png, NAME.ppm",
                "a render's image and its display picture (-o)");
    help_option(format, "NAME.XXXXXXXX.tmp", "an output being written, renamed into place "
                                             "at the end and removed if the command fails");
    help_option(format, "NAME.pfm.window", "a crop's record, for photon merge");
    help_section(format, "examples");
    help_lines(format, "photon /usr/local/share/photon/cornell.scene -o cornell.png\n"
                       "photon --mode 1996 --quality preview cornell-specular.scene -o s.png\n"
                       "photon --target-error 0.01 --error err.pfm cornell.scene -o ref.pfm\n"
                       "photon compare s.pfm ref.pfm --block 16 --diff diff.png\n"
                       "photon convert err.pfm -o err.png --false-colour\n");
}
