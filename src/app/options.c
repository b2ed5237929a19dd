/*
 * app/options.c -- parsing the render command's options (options.h); option_checks.c
 * refuses those that do not go together.
 */
#include "options.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/hash.h"
#include "../base/option_equals.h"
#include "../base/option_once.h"
#include "../modes/ppm2008.h"
#include "first_screen.h"
#include "help.h"
#include "option_checks.h"
#include "option_table.h"
#include "option_values.h"
#include "presets.h"
#include "suggest.h"

/* The modes of set (an option_spec.modes) into text[size], in the order of every_mode,
 * separated by ", ", the last by last (", " or " or "): "photons, 1994 or 1996". */
static void mode_list(unsigned set, const char *last, char *text, size_t size)
{
    size_t n = 0, listed = 0, count = 0;
    for (size_t m = 0; m < N_EVERY_MODE; m++)
        count += (set >> every_mode[m]) & 1u;
    text[0] = '\0';
    for (size_t m = 0; m < N_EVERY_MODE && n < size; m++) {
        if (!((set >> every_mode[m]) & 1u))
            continue;
        const char *separator = listed == 0 ? "" : listed + 1 == count ? last : ", ";
        n += (size_t)snprintf(text + n, size - n, "%s%s", separator, mode_name(every_mode[m]));
        listed++;
    }
}

/* What --help says of the modes an option is for, before its text: nothing when it is for
 * every mode, "not with MODES: " when it is for all but one or two, else "MODES: ". */
static void mode_note(unsigned set, char *text, size_t size)
{
    char modes[64];
    unsigned missing = FOR_ALL & ~set;
    if (missing == 0) {
        text[0] = '\0';
        return;
    }
    unsigned but_one = missing & (missing - 1);
    int most = (but_one & (but_one - 1)) == 0; /* one or two modes missing */
    mode_list(most ? missing : set, most ? " or " : ", ", modes, sizeof modes);
    snprintf(text, size, "%s%s: ", most ? "not with " : "", modes);
}

/* The number read_number() reads for a numeric option. */
static enum number_kind number_kind_of(const struct option_spec *spec)
{
    return spec->kind == OPT_INT || spec->kind == OPT_CROP ? NUMBER_WHOLE
           : spec->kind == OPT_REAL_ABOVE                  ? NUMBER_ABOVE
           : spec->kind == OPT_REAL_BETWEEN                ? NUMBER_BETWEEN
                                                           : NUMBER_REAL;
}

/* What --help says of spec's value after its text: its range, for a number. */
static void value_note(const struct option_spec *spec, char *text, size_t size)
{
    char range[96];
    int numeric = spec->kind == OPT_INT || spec->kind == OPT_REAL ||
                  spec->kind == OPT_REAL_ABOVE || spec->kind == OPT_REAL_BETWEEN ||
                  spec->kind == OPT_CROP;
    text[0] = '\0';
    if (!numeric)
        return;
    number_range(number_kind_of(spec), spec->min, spec->max, range, sizeof range);
    snprintf(text, size, " (%s: %s)", spec->kind == OPT_CROP ? "each" : spec->args, range);
}

/* photon --help MODE: the options that mode takes, its presets and --paper's words. */
static void print_mode_help(enum mode mode)
{
    printf("usage: photon --mode %s [options] SCENE\n\noptions of --mode %s (each mode's "
           "departures from its paper are switches:\n--NAME the default, --no-NAME the "
           "paper's; src/modes/README.md has why and the figures):\n", mode_name(mode),
           mode_name(mode));
    for (size_t i = 0; i < N_OPTION_SPECS; i++) {
        if (!((option_specs[i].modes >> mode) & 1u))
            continue;
        char left[40], range[128], text[1024];
        snprintf(left, sizeof left, "%s %s", option_specs[i].name, option_specs[i].args);
        value_note(&option_specs[i], range, sizeof range);
        snprintf(text, sizeof text, "%s%s", option_specs[i].help, range);
        help_option(HELP_TEXT, left, text);
    }
    print_presets(HELP_TEXT, (int)mode);
}

static void print_help(enum help_format format)
{
    help_begin(format, PHOTON_VERSION);
    if (format == HELP_ROFF)
        help_section(format, "synopsis");
    help_lines(format, "usage: photon [options] SCENE       render SCENE: a scene file, or an NFF file by its\n"
           "                                    .nff name (see README: Scene files)\n"
           "       photon compare A.pfm|.exr B.pfm|.exr [--diff OUT.png|.ppm] [--diff-absolute]\n"
           "                      [--block N] [--alpha ALPHA]\n"
           "                      [--ref-variance VB.pfm | --ref-error EB.pfm] [--confidence C]\n"
           "                      [--test-variance VA.pfm | --test-error EA.pfm] [--exit-status]\n"
           "                      (photon compare --help: the test and every field it prints)\n"
           "       photon plot A.csv [B.csv ...] -o PLOT.svg      (relmse against seconds)\n"
           "       photon plot --linear --x COL --y COL [--y COL]... [--x-title T]\n"
           "                   [--y-title T] A.csv [B.csv ...] -o PLOT.svg\n"
           "       photon probe SCENE --line X0 Y0 Z0 X1 Y1 Z1 --samples N -o FILE.csv\n"
           "                   [--normal NX NY NZ] [--photons N] [--gather N]\n"
           "                   [--differential R] [--seed S]   (irradiance along a line)\n"
           "       photon merge -o FULL.pfm|.exr TILE.pfm|.exr [TILE ...] [--exposure E]\n"
           "       photon convert IN.pfm|.exr -o OUT.png|.ppm [--exposure E | --false-colour\n"
           "                      [--min V] [--max V] [--log]]   (pictures of images and errors)\n"
           "       photon export --format pbrt|mitsuba|blender SCENE -o OUT.pbrt|.xml|.py\n"
           "                    [--spp N] [--channel R|G|B] [--width N] [--height N]\n"
           "                    (the scene for pbrt-v4, Mitsuba 3 or Blender; see README:\n"
           "                    Rendering our scenes elsewhere)\n");
    help_modes(format);
    help_section(format, "options");
    for (size_t i = 0; i < N_OPTION_SPECS; i++) {
        char left[40], note[80], range[128], text[1024];
        snprintf(left, sizeof left, "%s %s", option_specs[i].name, option_specs[i].args);
        mode_note(option_specs[i].modes, note, sizeof note);
        value_note(&option_specs[i], range, sizeof range);
        snprintf(text, sizeof text, "%s%s%s", note, option_specs[i].help, range);
        help_option(format, left, text);
    }
    help_option(format, "--help [MODE|all]", "print the first screen (with MODE: that mode's "
                                             "options, presets and --paper alone; with all: "
                                             "this) and exit");
    help_option(format, "--version", "print the version and exit");
    help_option(format, "--manual", "print this as a manual page (roff; make install writes "
                                    "photon.1 from it) and exit");
    print_presets(format, -1);
    help_manual_sections(format);
}

static const char *mode_at(size_t i) { return mode_name(every_mode[i]); } /* suggest.h */
static const char *spec_at(size_t i) { return option_specs[i].name; }

static int read_mode(const char *text, enum mode *mode, struct error *err)
{
    char hint[80];
    for (size_t i = 0; text != NULL && i < N_EVERY_MODE; i++)
        if (strcmp(text, mode_name(every_mode[i])) == 0) {
            *mode = every_mode[i];
            return 0;
        }
    did_you_mean(text, mode_at, N_EVERY_MODE, hint, sizeof hint);
    return error_set(err, "", 0, "--mode: unknown mode '%s'%s (available: direct, pt, photons, "
                     "1994, 1996, 2008, 2009)", text != NULL ? text : "nothing", hint);
}

/* --help, and the word after it (NULL for none): "all" the full list, a mode's name that
 * mode's help, anything else (a scene, another option) the first screen. */
static void print_help_about(const char *word)
{
    enum mode asked;
    if (word != NULL && strcmp(word, "all") == 0)
        print_help(HELP_TEXT);
    else if (word != NULL && read_mode(word, &asked, NULL) == 0)
        print_mode_help(asked);
    else
        print_first_screen();
}

static const struct option_spec *find_spec(const char *name)
{
    for (size_t i = 0; i < N_OPTION_SPECS; i++)
        if (strcmp(option_specs[i].name, name) == 0)
            return &option_specs[i];
    return NULL;
}

/* Applies option spec to the value words at argv[*i + 1 ...], advancing *i past them. */
static int apply_option(const struct option_spec *spec, char **argv, int argc, int *i,
                        struct options *o, struct error *err)
{
    char *field = (char *)o + spec->offset;
    const char *value = *i + 1 < argc ? argv[*i + 1] : NULL;
    double v;
    switch (spec->kind) {
    case OPT_FLAG:
        *(int *)field = strncmp(spec->name, "--no-", 5) != 0;
        return 0;
    case OPT_OFF: {
        char name[64];
        snprintf(name, sizeof name, "--%s", spec->name + strlen("--no-"));
        const struct option_spec *on = find_spec(name);
        assert(on != NULL && on->offset == spec->offset);
        if (on->kind == OPT_INT)
            *(int *)field = 0;
        else
            *(double *)field = 0;
        return 0;
    }
    case OPT_INT:
    case OPT_REAL:
    case OPT_REAL_ABOVE:
    case OPT_REAL_BETWEEN:
        (*i)++;
        if (read_number(spec->name, value, spec->min, spec->max, number_kind_of(spec), &v,
                        err) < 0)
            return -1;
        if (spec->kind == OPT_INT)
            *(int *)field = (int)v;
        else
            *(double *)field = v;
        return 0;
    case OPT_SEED:
        (*i)++;
        return read_seed(value, (uint64_t *)field, err);
    case OPT_MODE:
        (*i)++;
        return read_mode(value, (enum mode *)field, err);
    case OPT_QUALITY:
        (*i)++;
        return read_quality(value, (enum quality *)field, err);
    case OPT_OUTPUT:
        (*i)++;
        return read_output(value, field, &o->display, err);
    case OPT_STORE:
        (*i)++;
        return read_store(value, (int *)field, err);
    case OPT_FILE:
        (*i)++;
        if (value == NULL)
            return error_set(err, "", 0, "%s: expected a file name", spec->name);
        *(const char **)field = value;
        return 0;
    case OPT_CROP:
        for (int k = 0; k < 4; k++) {
            (*i)++;
            value = *i < argc ? argv[*i] : NULL;
            if (read_number(spec->name, value, spec->min, spec->max, NUMBER_WHOLE, &v, err) < 0)
                return -1;
            ((int *)field)[k] = (int)v;
        }
        o->has_crop = 1; /* apart from the values: 0 0 0 0 is an empty window, not none */
        return 0;
    }
    return -1;
}

/* The option given first on the command line (given[k]: the argv index of option_specs[k], 0
 * when absent) that means nothing for o->mode (option_spec.modes): -1 with *err naming
 * the modes it is for. */
static int check_modes(const struct options *o, const int given[N_OPTION_SPECS], struct error *err)
{
    size_t first = N_OPTION_SPECS;
    for (size_t k = 0; k < N_OPTION_SPECS; k++)
        if (given[k] > 0 && !((option_specs[k].modes >> o->mode) & 1u) &&
            (first == N_OPTION_SPECS || given[k] < given[first]))
            first = k;
    if (first == N_OPTION_SPECS)
        return 0;
    char modes[64];
    mode_list(option_specs[first].modes, " or ", modes, sizeof modes);
    return error_set(err, "", 0, "%s: only for --mode %s (this render is --mode %s)",
                     option_specs[first].name, modes, mode_name(o->mode));
}

/* Words to apply: word[first ... n - 1]. */
struct words {
    char **word;
    int first, n;
};

/* The argv index of an earlier word than i that gave spec, an option with a value; 0
 * when none. A second value would silently replace the first (--diff a.png --diff b.png
 * writes b.png alone). A switch is no such option: its last word states the whole
 * setting, and --no-NAME exists to undo an earlier --NAME (a script's, an alias's), as
 * a switch repeated says the same thing twice; so switches are never refused here. */
static int earlier_word(const struct option_spec *spec, const int given[N_OPTION_SPECS], int i)
{
    int k = (int)(spec - option_specs);
    int valued = spec->kind != OPT_FLAG && spec->kind != OPT_OFF;
    return valued && given[k] > 0 && given[k] != i ? given[k] : 0;
}

/* How many words of values follow spec's option: the words a message echoes with it. */
static int spec_values(const struct option_spec *spec)
{
    return spec->kind == OPT_FLAG || spec->kind == OPT_OFF ? 0
           : spec->kind == OPT_CROP                         ? 4
                                                            : 1;
}

/* Applies the words w to *o: options by option_specs[], any other word as the scene file; given[k]
 * becomes the index of the word that gave option_specs[k]. Returns 1 once --help or --version is
 * printed, -1 with *err filled on a bad word, else 0. */
static int apply_words(const struct words *w, struct options *o, int given[N_OPTION_SPECS],
                       struct error *err)
{
    char **argv = w->word;
    int argc = w->n;
    for (int i = w->first; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            print_help_about(i + 1 < argc ? argv[i + 1] : NULL);
            return 1;
        }
        if (strcmp(argv[i], "--manual") == 0) {
            print_help(HELP_ROFF);
            return 1;
        }
        if (strcmp(argv[i], "--version") == 0) {
            printf("photon %s\n", PHOTON_VERSION);
            return 1;
        }
        const struct option_spec *spec = find_spec(argv[i]);
        int earlier = spec != NULL ? earlier_word(spec, given, i) : 0;
        if (earlier > 0) /* one wording with the subcommands' (base/option_once.h) */
            return option_given_again("", argc, argv, earlier, i, spec_values(spec), err);
        if (spec != NULL) {
            given[spec - option_specs] = i;
            if (apply_option(spec, argv, argc, &i, o, err) < 0)
                return -1;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            char hint[80];
            did_you_mean(argv[i], spec_at, N_OPTION_SPECS, hint, sizeof hint);
            return error_set(err, "", 0, "unknown option '%s'%s (see photon --help)", argv[i],
                             hint);
        } else if (o->scene_path != NULL) {
            return error_set(err, "", 0, "more than one scene file: '%s' and '%s'",
                             o->scene_path, argv[i]);
        } else {
            o->scene_path = argv[i];
        }
    }
    return 0;
}

/* Applies the words of a layer that stands before the user's (a preset, --paper); name
 * heads the message of a bad word, which would be a defect of the table. */
static int apply_layer(const struct preset_words *layer, const char *name, struct options *o,
                       struct error *err)
{
    struct words list = {(char **)layer->word, 0, layer->n_words};
    int layer_given[N_OPTION_SPECS] = {0};
    struct error inner;
    if (apply_words(&list, o, layer_given, &inner) != 0)
        return error_set(err, "", 0, "%s: %s", name, inner.message);
    return 0;
}

/* The defaults, the preset's words, --paper's, then the user's (argv[1 ...]): a first pass
 * reads the user's alone for the mode, quality and --paper (refusing a bad word first), the
 * second starts again from the defaults; given[] as the user's words leave it. */
static int apply_preset_and_words(int argc, char **argv, struct options *o,
                                  int given[N_OPTION_SPECS], struct error *err)
{
    struct words user = {argv, 1, argc};
    option_defaults(o);
    int status = apply_words(&user, o, given, err);
    if (status != 0)
        return status;
    enum quality quality = o->quality;
    int paper = o->paper, user_specular_spp = o->specular_spp;
    struct preset_words preset, as_written;
    preset_words(o->mode, quality, &preset);
    paper_words(o->mode, paper, &as_written);
    option_defaults(o);
    char name[32];
    snprintf(name, sizeof name, "--quality %s", quality_name(quality));
    if (apply_layer(&preset, name, o, err) < 0 || apply_layer(&as_written, "--paper", o, err) < 0)
        return -1;
    status = apply_words(&user, o, given, err); /* 0: the first pass read the same words */
    /* A preset's --specular-spp gives way to a larger --spp of the user's: fewer samples
     * in the specular pixels than in the others is what the user did not ask for. */
    if (user_specular_spp == 0 && o->specular_spp > 0 && o->specular_spp < o->spp)
        o->specular_spp = o->spp;
    return status;
}

/* command_words.given (option_checks.h) over given[]: where the command line gave the
 * option called name, 0 when it did not. */
static int given_word(const void *given, const char *name)
{
    const struct option_spec *spec = find_spec(name);
    assert(spec != NULL);
    return ((const int *)given)[spec - option_specs];
}

static int parse_split_options(int argc, char **argv, struct options *o, struct error *err);

int parse_options(int argc, char **argv, struct options *o, struct error *err)
{
    struct option_arity arity[N_OPTION_SPECS + 1]; /* for --NAME=VALUE (option_equals.h) */
    for (size_t k = 0; k < N_OPTION_SPECS; k++) {
        arity[k].name = option_specs[k].name;
        arity[k].values = spec_values(&option_specs[k]);
    }
    arity[N_OPTION_SPECS].name = NULL;
    char **split;
    int split_argc = 0;
    int status = split_equals("", argc, argv, arity, &split, &split_argc, err);
    if (status == 0)
        status = parse_split_options(split_argc, split, o, err);
    xfree(split);
    return status;
}

/* parse_options() once every --NAME=VALUE is two words. */
static int parse_split_options(int argc, char **argv, struct options *o, struct error *err)
{
    int given[N_OPTION_SPECS] = {0};
    int status = apply_preset_and_words(argc, argv, o, given, err);
    if (status != 0)
        return status;
    if (o->scene_path == NULL)
        return error_set(err, "", 0, "no scene file given (see photon --help)");
    if (o->output[0] == '\0')
        default_output(o->scene_path, o->output);
    if ((o->reference == NULL) != (o->report == NULL))
        return error_set(err, "", 0, "--reference and --report go together");
    if (o->target_error > 0 && o->spp == 0 && o->mode != MODE_PPM2008) /* 2008: --passes */
        o->spp = MAX_SPP; /* the target ends the render, or the time limit */
    mode_defaults(o);
    if (o->cone > 0 && o->cone < 1)
        return error_set(err, "", 0, "--cone: k must be 0 (no filter) or at least 1");
    if (o->specular_spp == 0) /* spp <= MAX_SPP, so the product cannot overflow */
        o->specular_spp = (o->mode == MODE_JENSEN1996 || o->mode == MODE_JENSEN1994) &&
                                  !o->paper
                              ? (int)fmin(SPECULAR_SPP_FACTOR * o->spp, MAX_SPP)
                              : o->spp;
    struct command_words words = {given_word, given};
    if (check_combinations(o, &words, err) < 0)
        return -1;
    return check_modes(o, given, err); /* after the checks above, whose messages say why */
}

/* The options that change no pixel of the PFM: outputs, what is printed or shown, the
 * window, checkpoints and reports (they only look at the image), and the file of global
 * work, which holds what the render would compute itself, bit for bit (tests/test_merge.c).
 * options_hash() covers every other option. --time-limit is here because a hash cannot
 * capture it (the pixels depend on the machine's speed: tile.h records it apart);
 * --quality because its words are hashed themselves, as if spelled out. */
static const char *const outside_pixels[] = {
    "-o", "--crop", "--stats", "--progress", "--no-progress", "--exposure", "--reference",
    "--report", "--variance", "--error", "--block-error", "--checkpoint", "--time-limit",
    "--save-photons", "--load-photons", "--quality", "--paper",
};

static int changes_pixels(const struct option_spec *spec)
{
    for (size_t i = 0; i < sizeof outside_pixels / sizeof outside_pixels[0]; i++)
        if (strcmp(spec->name, outside_pixels[i]) == 0)
            return 0;
    return 1;
}

/* spec's value in o as text: exact for reals (17 significant digits round-trip a double),
 * and the same whatever order or spelling the command line used. */
static void option_text(const struct option_spec *spec, const struct options *o, char *text,
                        size_t size)
{
    const char *field = (const char *)o + spec->offset;
    switch (spec->kind) {
    case OPT_REAL:
    case OPT_REAL_ABOVE:
    case OPT_REAL_BETWEEN:
        snprintf(text, size, "%s=%.17g\n", spec->name, *(const double *)field);
        return;
    case OPT_SEED:
        snprintf(text, size, "%s=%llu\n", spec->name,
                 (unsigned long long)*(const uint64_t *)field);
        return;
    case OPT_MODE:
        snprintf(text, size, "%s=%s\n", spec->name, mode_name(*(const enum mode *)field));
        return;
    case OPT_FLAG:
    case OPT_INT:
    case OPT_STORE:
        snprintf(text, size, "%s=%d\n", spec->name, *(const int *)field);
        return;
    case OPT_OFF: /* its field is hashed under the option it turns off */
        text[0] = '\0';
        return;
    case OPT_QUALITY:
    case OPT_OUTPUT:
    case OPT_FILE:
    case OPT_CROP:
        break;
    }
    /* A file that changes pixels must have its bytes hashed where it is read, as the
     * scene's lines are (scene_hash_line); its name says nothing of them. */
    assert(!"--quality and the options naming files or the window are in outside_pixels[]");
    snprintf(text, size, "%s\n", spec->name);
}

uint64_t options_hash(const struct options *o, uint64_t h)
{
    char text[128];
    snprintf(text, sizeof text, "photon %s\n", PHOTON_VERSION);
    h = fnv1a(h, text, strlen(text));
    for (size_t i = 0; i < N_OPTION_SPECS; i++)
        if (changes_pixels(&option_specs[i])) {
            option_text(&option_specs[i], o, text, sizeof text);
            h = fnv1a(h, text, strlen(text));
        }
    return h;
}
