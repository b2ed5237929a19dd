/*
 * app/first_screen.c -- the first screen of photon's help (first_screen.h).
 *
 * Each entry is help.c's text layout, an option's left column and its text, on one line:
 * a text takes the 71 columns right of the left column at most, so that it is not wrapped
 * onto a second line that the screen has no room for.
 */
#include "first_screen.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

#include "commands.h"
#include "help.h"
#include "option_table.h"
#include "option_values.h"

/* What a mode is, in a line. A switch, so that a mode added to enum mode without a line
 * here is a compiler's warning (-Wswitch). */
static const char *mode_summary(enum mode mode)
{
    switch (mode) {
    case MODE_DIRECT:
        return "Whitted-style: lights sampled, mirrors and glass followed; no indirect";
    case MODE_PT:
        return "unbiased path tracing, the ground truth; --error states its noise";
    case MODE_PHOTONS:
        return "the global photon map seen directly (Jensen 1996, Fig. 4)";
    case MODE_JENSEN1994:
        return "Jensen & Christensen 1994: projection maps, irradiance cache";
    case MODE_JENSEN1996:
        return "Jensen 1996: global and caustic maps, final gather, irradiance cache";
    case MODE_PPM2008:
        return "progressive photon mapping (Hachisuka, Ogaki & Jensen 2008)";
    case MODE_SPPM2009:
        return "stochastic progressive photon mapping (Hachisuka & Jensen 2009)";
    }
    return "";
}

void help_modes(enum help_format format)
{
    help_section(format, "modes (--mode NAME; pt unless given)");
    for (size_t m = 0; m < N_EVERY_MODE; m++)
        help_option(format, mode_name(every_mode[m]), mode_summary(every_mode[m]));
}

/* The options most renders want, by the table's names (one or two on a line), and a line
 * of text each; their ranges and defaults are in photon --help all. */
static const struct {
    const char *name, *also, *text;
} common[] = {
    {"-o", NULL, "the image; a PNG (.ppm: PPM) beside it (default: SCENE's name.pfm)"},
    {"--quality", NULL, "preview, default or reference: the mode's preset of options"},
    {"--spp", NULL, "camera samples per pixel (2008: eye rays per pixel; not 2009)"},
    {"--passes", NULL, "2008, 2009: photon passes (2009: a new eye path a pixel each)"},
    {"--seed", NULL, "random seed (default 1): the same seed gives the same bytes"},
    {"--width", "--height", "the image's size in pixels (default: the scene's)"},
    {"--time-limit", NULL, "start no new pass once this many CPU seconds are used"},
    {"--error", NULL, "pt, 2008, 2009: also write each pixel's bound on its error"},
    {"--target-error", NULL, "pt, 2008, 2009: sample until each block's bound is at most E x mean"},
    {"--paper", NULL, "the mode's paper as written: every departure from it off"},
    {"--stats", NULL, "print the render's figures (key=value) on stderr"},
};

/* The option table's row for name; every name above has one. */
static const struct option_spec *spec_named(const char *name)
{
    for (size_t i = 0; i < N_OPTION_SPECS; i++)
        if (strcmp(option_specs[i].name, name) == 0)
            return &option_specs[i];
    assert(!"the first screen names an option the table has");
    return &option_specs[0];
}

/* "NAME ARGS" of the table's row for name, as the full list's left column has it (a
 * switch's ARGS is empty), into text[size] after the n characters already there. */
static void append_left(const char *name, char *text, size_t size, size_t n)
{
    const struct option_spec *spec = spec_named(name);
    snprintf(text + n, size - n, "%s%s%s", spec->name, spec->args[0] != '\0' ? " " : "",
             spec->args);
}

static void print_common_options(void)
{
    help_section(HELP_TEXT, "common options (photon --help all: every option, range, default)");
    for (size_t i = 0; i < sizeof common / sizeof common[0]; i++) {
        char left[64] = "";
        append_left(common[i].name, left, sizeof left, 0);
        if (common[i].also != NULL) {
            size_t n = strlen(left);
            n += (size_t)snprintf(left + n, sizeof left - n, ", ");
            append_left(common[i].also, left, sizeof left, n);
        }
        help_option(HELP_TEXT, left, common[i].text);
    }
}

void print_first_screen(void)
{
    help_lines(HELP_TEXT, "usage: photon [options] SCENE      render SCENE: a scene file, or an "
                          "NFF file by its .nff name\n"
                          "       photon COMMAND ARGS...      one of the commands below\n");
    help_modes(HELP_TEXT);
    print_common_options();
    help_section(HELP_TEXT, "commands (photon COMMAND ARGS...)");
    for (size_t i = 0; i < N_COMMANDS; i++)
        help_option(HELP_TEXT, commands[i].name, commands[i].summary);
    help_section(HELP_TEXT, "more");
    help_option(HELP_TEXT, "photon --help MODE", "that mode's options, its presets and "
                                                 "--paper's words");
    help_option(HELP_TEXT, "photon --help all", "every option with its range and default, "
                                                "every preset");
    help_option(HELP_TEXT, "photon COMMAND --help", "a command's usage and options");
    help_option(HELP_TEXT, "photon --manual", "--help all as a manual page (roff); "
                                              "--version: the version");
}
