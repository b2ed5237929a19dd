/*
 * app/convert.c -- `photon convert`: one image file to a PNG or PPM to look at (convert.h).
 *
 * Without --false-colour the picture is the display image a render writes beside its PFM,
 * the same bytes for the same --exposure (display_encode(), through png_write() and
 * ppm_write()). With it, each pixel's number (the largest of R, G, B) in false colour with
 * the scale beside the image (image/false_colour.c: the map, the default range, the
 * layout). The output is checked before the input is read, refused when it is the input,
 * and written whole or not at all (base/output.h).
 */
#include "convert.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

#include "../base/number.h"
#include "../base/option_once.h"
#include "../base/output.h"
#include "../image/false_colour.h"
#include "../image/png.h"
#include "option_values.h"
#include "suggest.h"

/* The usage in two parts: one line in a message, two in --help (within 100 columns). */
#define CONVERT_USAGE_NAMES "usage: photon convert IN.pfm|.exr -o OUT.png|.ppm"
#define CONVERT_USAGE_OPTIONS "[--exposure E | --false-colour [--min V] [--max V] [--log]]"
#define CONVERT_USAGE CONVERT_USAGE_NAMES " " CONVERT_USAGE_OPTIONS

/* What `photon convert` was asked to do. */
struct convert_args {
    const char *input, *output;         /* IN.pfm or .exr, -o OUT.png or OUT.ppm          */
    const char *exposure_text;          /* each value as given, or NULL                   */
    const char *min_text, *max_text;
    int false_colour, log;              /* --false-colour, --log                          */
    double exposure;                    /* 1 unless given                                 */
    struct false_colour fc;             /* the ends given, in fc.min and fc.max           */
    struct option_once once;            /* the options with a value read so far           */
};

/* Also the names for the near miss of an unknown option (app/suggest.h). */
const struct option_arity convert_options[] = {
    {"-o", 1},  {"--exposure", 1}, {"--false-colour", 0}, {"--false-color", 0},
    {"--min", 1}, {"--max", 1},    {"--log", 0},          {"--help", 0},
    {NULL, 0},
};
#define N_OPTION_NAMES (sizeof convert_options / sizeof convert_options[0] - 1)

static const char *option_at(size_t i)
{
    return convert_options[i].name;
}

/* `photon convert --help`. */
static const char convert_help[] =
    CONVERT_USAGE_NAMES "\n                      " CONVERT_USAGE_OPTIONS "\n"
    "Writes an image file (a PFM: photon's -o, --variance, --error, --block-error, or\n"
    "anyone's) as a picture to look at, a PNG or, for OUT.ppm, a binary PPM.\n"
    "  --exposure E      linear value x E, clamped to [0, 1], sRGB-encoded: the display\n"
    "                    image a render writes (default 1)\n"
    "  --false-colour    each pixel's largest channel (for an error image, the worst\n"
    "                    channel's error) in viridis, dark blue for --min to yellow for\n"
    "                    --max, with a colour bar and its values to the right of the image\n"
    "                    (--false-color too)\n"
    "  --min V, --max V  the bar's ends. Default: 0 to the 99th percentile of the pixels'\n"
    "                    values, rounded to two digits, labelled \"p99\" (the largest value\n"
    "                    when that is 0); beyond them, the ends' colours\n"
    "  --log             by log10 of the value (default --min: --max / 1000)\n"
    "The bar takes a strip s (27 + 6 n) pixels wide to the right of the image, n the\n"
    "longest label's characters, s = image height / 256 (1 to 4); a picture less than\n"
    "60 s pixels tall is made that tall, black below the image.\n";

/* An option's value: the next argument; *i advanced past it. -1 with *err filled when
 * missing or given twice (once records the options read). */
static int option_value(int argc, char **argv, int *i, const char **value,
                        struct option_once *once, struct error *err)
{
    const char *name = argv[*i];
    if (option_once(once, "convert", argc, argv, *i, 1, err) < 0)
        return -1;
    if (*i + 1 == argc)
        return error_set(err, "", 0, "convert: %s needs a value; " CONVERT_USAGE, name);
    *value = argv[++*i];
    return 0;
}

/* One option at argv[*i] into args; -1 with *err filled. */
static int parse_option(int argc, char **argv, int *i, struct convert_args *args,
                        struct error *err)
{
    const char *name = argv[*i];
    const char **value = strcmp(name, "-o") == 0           ? &args->output
                         : strcmp(name, "--exposure") == 0 ? &args->exposure_text
                         : strcmp(name, "--min") == 0      ? &args->min_text
                         : strcmp(name, "--max") == 0      ? &args->max_text
                                                           : NULL;
    if (value != NULL)
        return option_value(argc, argv, i, value, &args->once, err);
    int *flag = strcmp(name, "--false-colour") == 0 || strcmp(name, "--false-color") == 0
                    ? &args->false_colour
                : strcmp(name, "--log") == 0 ? &args->log
                                             : NULL;
    if (flag != NULL) {
        *flag = 1;
        return 0;
    }
    char hint[96];
    did_you_mean(name, option_at, N_OPTION_NAMES, hint, sizeof hint);
    return error_set(err, "", 0, "convert: unknown option '%s'%s; " CONVERT_USAGE, name, hint);
}

/* A --min or --max value into *value: any finite number. */
static int read_end(const char *name, const char *text, double *value, struct error *err)
{
    if (!number_parse(text, 0, value))
        return error_set(err, "", 0, "convert: %s: expected a number, got '%s'", name, text);
    return 0;
}

/* What the options say together: each needs what it applies to, the range its order. */
static int check_args(struct convert_args *args, struct error *err)
{
    size_t n = args->output != NULL ? strlen(args->output) : 0;
    struct false_colour *fc = &args->fc;
    if (args->input == NULL)
        return error_set(err, "", 0, "convert: no input image; " CONVERT_USAGE);
    if (args->output == NULL)
        return error_set(err, "", 0, "convert: no output: give -o OUT.png or OUT.ppm");
    if (n < 5 || (strcmp(args->output + n - 4, ".png") != 0 &&
                  strcmp(args->output + n - 4, ".ppm") != 0))
        return error_set(err, "", 0, "convert: -o '%s': expected a file name ending in .png "
                         "or .ppm", args->output);
    if (args->exposure_text != NULL && args->false_colour)
        return error_set(err, "", 0, "convert: --exposure is for the picture by exposure; "
                         "--false-colour takes --min and --max");
    if ((args->min_text != NULL || args->max_text != NULL || args->log) &&
        !args->false_colour)
        return error_set(err, "", 0, "convert: %s needs --false-colour",
                         args->min_text ? "--min" : args->max_text ? "--max" : "--log");
    args->exposure = 1.0;
    if (args->exposure_text != NULL && read_number("--exposure", args->exposure_text, 0,
                                                   1e30, NUMBER_REAL, &args->exposure,
                                                   err) < 0)
        return -1;
    fc->log = args->log;
    if ((args->min_text != NULL && read_end("--min", args->min_text, &fc->min, err) < 0) ||
        (args->max_text != NULL && read_end("--max", args->max_text, &fc->max, err) < 0))
        return -1;
    if (args->min_text != NULL && args->max_text != NULL && !(fc->min < fc->max))
        return error_set(err, "", 0, "convert: --min %s must be below --max %s",
                         args->min_text, args->max_text);
    if (args->log && ((args->min_text != NULL && !(fc->min > 0)) ||
                      (args->max_text != NULL && !(fc->max > 0))))
        return error_set(err, "", 0, "convert: --log needs --min and --max above 0, got %s",
                         args->min_text != NULL && !(fc->min > 0) ? args->min_text
                                                                   : args->max_text);
    return 0;
}

/* The arguments after "convert"; 1 when --help was printed, -1 with *err filled. */
static int parse_convert_args(int argc, char **argv, struct convert_args *args,
                              struct error *err)
{
    memset(args, 0, sizeof *args);
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(convert_help, stdout);
            return 1;
        }
        if (argv[i][0] == '-' && argv[i][1] != '\0') {
            if (parse_option(argc, argv, &i, args, err) < 0)
                return -1;
        } else if (args->input == NULL) {
            args->input = argv[i];
        } else {
            return error_set(err, "", 0, "convert: more than one input image ('%s', '%s'); "
                             CONVERT_USAGE, args->input, argv[i]);
        }
    }
    return check_args(args, err);
}

/* The one place convert reads its input, a PFM or an OpenEXR file. image_read_bounds(),
 * not image_read(): an --error image holds +Inf where a bound could not be stated, and
 * should be looked at too (+Inf takes the top colour, or full white by exposure). */
static struct image *read_input(const char *name, struct error *err)
{
    return image_read_bounds(name, err);
}

/* Reads the input and writes the picture (not yet published); -1 with *err filled. */
static int convert(struct convert_args *args, struct error *err)
{
    struct image *img = read_input(args->input, err);
    if (img == NULL)
        return -1;
    int status;
    size_t n = strlen(args->output);
    if (args->false_colour) {
        false_colour_range(img, args->min_text != NULL, args->max_text != NULL, &args->fc);
        struct picture p = false_colour_picture(img, &args->fc);
        status = picture_write(args->output, &p, err);
        picture_free(&p);
    } else if (strcmp(args->output + n - 4, display_suffix(DISPLAY_PPM)) == 0) {
        status = ppm_write(args->output, img, args->exposure, err);
    } else {
        status = png_write(args->output, img, args->exposure, err);
    }
    image_free(img);
    return status;
}

int convert_command(int argc, char **argv)
{
    assert(argc >= 1 && strcmp(argv[0], "convert") == 0);
    struct error err;
    struct convert_args args;
    int parsed = parse_convert_args(argc, argv, &args, &err);
    if (parsed == 1)
        return 0;
    if (parsed < 0 || output_check_one(args.output, "-o", &err) < 0 ||
        convert(&args, &err) < 0 || outputs_publish(&err) < 0) {
        error_print(&err);
        return error_exit_status(&err);
    }
    return 0;
}
