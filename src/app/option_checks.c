/*
 * app/option_checks.c -- the refusals of options that are good one by one but not together
 * (option_checks.h).
 *
 * First the options a mode cannot take for a reason of its own (--adaptive in 2008, whose
 * pixels are not means of independent samples). Then the options that do nothing given
 * the others: the render with them is the render without them, so taking them silently
 * would let the user think they had changed it. Each is idle by the code named:
 *
 *   --footprints, --fit-radius, --no-fit-radius with --radius (2008, 2009):
 *     ppm_initial_radius() returns --radius before it reads either, 2008's
 *     caustic_radius() too, and 2009 fits a radius to the surface only without it.
 *   --disc-coverage with --no-precomputed-irradiance (1996): the coverage is taken only
 *     by the records of precomputed irradiance (precompute_irradiance()), and there are
 *     none. --no-disc-coverage is taken there: it states Eq. 3's pi r^2, which every
 *     estimate then uses, and --paper's words spelled out carry it.
 *   --bounded-reach, --gradient-limit and their --no- forms with --cache-accuracy 0
 *     (1996): they set a cache record's R (record_reach_at()), and with no cache a
 *     gathered record's R is read by nothing; its irradiance does not depend on it.
 *   --caustic-gather, --caustic-radius-fraction, --cone with --caustic-photons 0 and
 *     no --one-map (1996): they are the caustic estimate's alone, and no caustic map is
 *     built, so caustics() returns 0 before estimating.
 *   --adaptive when no pixel takes more than ADAPTIVE_MIN_SPP samples: the rule is read
 *     only at that many samples or more, short of the pixel's target (render_pass()).
 *   --checkpoint K with K >= --passes (2008, 2009): the first write would follow pass K,
 *     and the image is written after the last pass anyway.
 *   --confidence without --error or --target-error: only the error bound reads it.
 * Not refused, since they do something: --caustic-footprints K with --radius, which
 * still turns 2008's caustic estimate on (at --radius, as --help says), and --alpha with
 * --passes 1, whose Eq. 12 and Eq. 9 cancel in the estimate only up to rounding.
 */
#include "option_checks.h"

#include <stdio.h>
#include <string.h>

#include "../modes/pixel_error.h"
#include "../modes/render.h"
#include "option_values.h"
#include "presets.h"

/* Whether a layer's words (a preset's, --paper's) name the option called name. */
static int layer_names(const struct preset_words *layer, const char *name)
{
    for (int i = 0; i < layer->n_words; i++)
        if (strcmp(layer->word[i], name) == 0)
            return 1;
    return 0;
}

/* Where o's value of the option called name came from, for a message: "" when the command
 * line gave it, else "from --paper", "from --quality NAME" or "the mode's default", into
 * text[size]. --paper's words stand after the preset's, so they are asked first. */
static void origin(const struct options *o, const struct command_words *words,
                   const char *name, char *text, size_t size)
{
    struct preset_words preset, as_written;
    preset_words(o->mode, o->quality, &preset);
    paper_words(o->mode, o->paper, &as_written);
    if (words->given(words->table, name) > 0)
        text[0] = '\0';
    else if (layer_names(&as_written, name))
        snprintf(text, size, "from --paper");
    else if (layer_names(&preset, name))
        snprintf(text, size, "from --quality %s", quality_name(o->quality));
    else
        snprintf(text, size, "the mode's default");
}

/* "NAME VALUE" ("NAME" when value is empty), and where it came from in brackets when the
 * command line did not give it ("--passes 8 (from --quality preview)",
 * "--no-precomputed-irradiance (from --paper)"), into text[size]. */
static void setting_text(const struct options *o, const struct command_words *words,
                         const char *name, const char *value, char *text, size_t size)
{
    char from[48];
    origin(o, words, name, from, sizeof from);
    snprintf(text, size, "%s%s%s%s%s%s", name, value[0] != '\0' ? " " : "", value,
             from[0] != '\0' ? " (" : "", from, from[0] != '\0' ? ")" : "");
}

/* setting_text() of an option's number. */
static void setting(const struct options *o, const struct command_words *words,
                    const char *name, double value, char *text, size_t size)
{
    char number[32];
    snprintf(number, sizeof number, "%.15g", value);
    setting_text(o, words, name, number, text, size);
}

/* --save-photons and --load-photons: one of them, in a mode that has global work to
 * save. */
static int check_global_work_options(const struct options *o, struct error *err)
{
    const char *name = o->save_photons != NULL ? "--save-photons" : "--load-photons";
    if (o->save_photons == NULL && o->load_photons == NULL)
        return 0;
    if (o->save_photons != NULL && o->load_photons != NULL)
        return error_set(err, "", 0, "--save-photons and --load-photons: give one or the "
                                     "other");
    if (o->mode == MODE_DIRECT || o->mode == MODE_PT)
        return error_set(err, "", 0, "%s: mode %s has no global work to save (every sample "
                         "belongs to its pixel)", name, mode_name(o->mode));
    if (o->mode == MODE_PPM2008 || o->mode == MODE_SPPM2009)
        return error_set(err, "", 0, "%s: mode %s traces new photons in every pass; they "
                         "are not saved (their tracing is the smaller part of a tile's "
                         "work: scripts/README.md)", name, mode_name(o->mode));
    return 0;
}

/* Refuses the option of names[0 .. n - 1] that the command line gave first, as doing
 * nothing with `with` (the setting that leaves it idle) for the reason `why`; 0 when it
 * gave none of them. */
static int refuse_idle(const struct command_words *words, const char *const *names, size_t n,
                       const char *with, const char *why, struct error *err)
{
    const char *first = NULL;
    int first_word = 0;
    for (size_t i = 0; i < n; i++) {
        int word = words->given(words->table, names[i]);
        if (word > 0 && (first == NULL || word < first_word)) {
            first = names[i];
            first_word = word;
        }
    }
    if (first == NULL)
        return 0;
    return error_set(err, "", 0, "%s: does nothing with %s, %s", first, with, why);
}

#define N_NAMES(names) (sizeof names / sizeof names[0])

/* The options that do nothing given the others (the top of this file says why each). */
static int check_idle(const struct options *o, const struct command_words *words,
                      struct error *err)
{
    static const char *const footprint_r0[] = {"--footprints", "--fit-radius",
                                               "--no-fit-radius"};
    static const char *const disc_coverage[] = {"--disc-coverage"};
    static const char *const record_reach[] = {"--bounded-reach", "--no-bounded-reach",
                                               "--gradient-limit", "--no-gradient-limit"};
    static const char *const caustic_estimate[] = {"--caustic-gather",
                                                   "--caustic-radius-fraction", "--cone"};
    static const char *const adaptive[] = {"--adaptive"};
    static const char *const checkpoint[] = {"--checkpoint"};
    static const char *const confidence[] = {"--confidence"};
    int progressive = o->mode == MODE_PPM2008 || o->mode == MODE_SPPM2009;
    char with[96], why[160];
    if (progressive && o->radius > 0 &&
        refuse_idle(words, footprint_r0, N_NAMES(footprint_r0), "--radius",
                    "which sets R0 in scene units", err) < 0)
        return -1;
    if (progressive && o->checkpoint >= o->passes) {
        setting(o, words, "--passes", o->passes, with, sizeof with);
        snprintf(why, sizeof why, "whose last pass writes the image anyway (the first "
                 "checkpoint would follow pass %d)", o->checkpoint);
        if (refuse_idle(words, checkpoint, 1, with, why, err) < 0)
            return -1;
    }
    if (o->mode == MODE_JENSEN1996 && o->precomputed_irradiance == 0) {
        setting_text(o, words, "--no-precomputed-irradiance", "", with, sizeof with);
        if (refuse_idle(words, disc_coverage, 1, with, "which makes no records of "
                        "precomputed irradiance, the only estimates it acts on in mode "
                        "1996", err) < 0)
            return -1;
    }
    if (o->mode == MODE_JENSEN1996 && o->cache_accuracy == 0) {
        setting(o, words, "--cache-accuracy", 0, with, sizeof with);
        if (refuse_idle(words, record_reach, N_NAMES(record_reach), with, "which keeps no "
                        "irradiance cache, whose records' R it shapes", err) < 0)
            return -1;
    }
    if (o->mode == MODE_JENSEN1996 && o->caustic_photons == 0 && !o->one_map) {
        setting(o, words, "--caustic-photons", 0, with, sizeof with);
        if (refuse_idle(words, caustic_estimate, N_NAMES(caustic_estimate), with,
                        "which makes no caustic map (without --one-map), and mode 1996 "
                        "applies it to caustic estimates alone", err) < 0)
            return -1;
    }
    if (!progressive && o->adaptive > 0 && o->specular_spp <= ADAPTIVE_MIN_SPP) {
        const char *most = o->specular_spp > o->spp ? "--specular-spp" : "--spp";
        setting(o, words, most, o->specular_spp, with, sizeof with);
        snprintf(why, sizeof why, "as no pixel takes more samples and the rule stops one "
                 "only short of its last, from %d on", ADAPTIVE_MIN_SPP);
        if (refuse_idle(words, adaptive, 1, with, why, err) < 0)
            return -1;
    }
    if (o->error == NULL && o->target_error == 0 &&
        refuse_idle(words, confidence, 1, "no --error or --target-error",
                    "whose bound alone it sets", err) < 0)
        return -1;
    return 0;
}

/* 2008's bound (modes/ppm_error.h) is made from the spread of its passes, which re-sample
 * neither the hit points nor the eye rays of the ray tracing pass: it holds where those
 * carry only the photons' light after a bounce, smooth over several pixels, and misses
 * where they carry the light's edges. Measured against closed forms (tests/
 * test_error_2008.c): with the direct light from photons the truth fell within the 95%
 * bound in 0.66 of point-over-plane's pixels at 32 x 32 (one merged hit point a pixel)
 * and 0.91 of area-over-floor's without merging (the light's outline splits a pixel's
 * --spp rays); with the emission seen by the --spp rays alone, the blocks on the light's
 * outline were stated exact (their rays fixed) and erred. */
static int check_error_2008(const struct options *o, const struct command_words *words,
                            const char *name, struct error *err)
{
    char with[96];
    if (!o->direct_light_samples) {
        setting_text(o, words, "--no-direct-light-samples", "", with, sizeof with);
        return error_set(err, "", 0, "%s: not with %s: the photons then bring the direct "
                         "light to hit points fixed by the first eye rays, whose aliasing "
                         "(a merged hit point one point of the light for its pixel, a "
                         "shadow's or a light's outline split by --spp rays) no spread of "
                         "the passes states (the truth within the 95%% bound in 0.66 of "
                         "point-over-plane's pixels)", name, with);
    }
    if (!o->resample_emission) {
        setting_text(o, words, "--no-resample-emission", "", with, sizeof with);
        return error_set(err, "", 0, "%s: not with %s: the emission seen is then the "
                         "--spp first eye rays' alone, fixed, whose aliasing on a light's "
                         "outline no spread of the passes states (area-over-floor's blocks "
                         "there were stated exact and erred)", name, with);
    }
    return 0;
}

/* The bound of --error and --target-error (modes/pixel_error.h; 2008 and 2009:
 * modes/sppm_error.h) holds for the pixel's expected value only where that is the truth
 * (or its bias is stated) and its samples (2008, 2009: passes) are many enough to see
 * their rare values. */
static int check_error_bound(const struct options *o, const struct command_words *words,
                             struct error *err)
{
    if (o->error == NULL && o->target_error == 0)
        return 0;
    const char *name = o->error != NULL ? "--error" : "--target-error";
    if (o->mode == MODE_DIRECT)
        return error_set(err, "", 0, "%s: --mode direct states no bound: it leaves out "
                         "indirect light by design, a bias no spread of its samples shows; "
                         "pt, photons, 2008 and 2009 state one", name);
    if (o->mode == MODE_JENSEN1994 || o->mode == MODE_JENSEN1996)
        return error_set(err, "", 0, "%s: --mode %s states no bound yet: every pixel shares "
                         "its photon maps and irradiance cache, whose noise and bias no "
                         "spread of one pixel's samples shows; pt, photons, 2008 and 2009 "
                         "state one", name, mode_name(o->mode));
    if (o->mode == MODE_PHOTONS && o->target_error > 0)
        return error_set(err, "", 0, "--target-error: --mode photons cannot refine its image: "
                         "its one photon map is made before the pixels; give --photons and "
                         "--gather, and --error states how far the image is");
    int passes = o->mode != MODE_PT, n = passes ? o->passes : o->spp;
    if (o->mode != MODE_PHOTONS && n < ERROR_MIN_SPP)
        return error_set(err, "", 0, "%s: needs %s >= %d (with %d, even the spread "
                         "pooled over 5 x 5 pixels misses the rare bright samples, and the "
                         "bound with it)", name, passes ? "--passes" : "--spp", ERROR_MIN_SPP,
                         n);
    if (o->adaptive > 0)
        return error_set(err, "", 0, "%s: not with --adaptive, whose rule stops a pixel by "
                         "its own samples and so biases it by an amount no spread states",
                         name);
    if (o->max_depth >= 0 && o->max_depth < MAX_DEPTH_LIMIT)
        return error_set(err, "", 0, "%s: not with --max-depth %d, which leaves out the "
                         "light of longer paths, a bias no spread states", name,
                         o->max_depth);
    return o->mode == MODE_PPM2008 ? check_error_2008(o, words, name, err) : 0;
}

int check_combinations(const struct options *o, const struct command_words *words,
                       struct error *err)
{
    int progressive = o->mode == MODE_PPM2008 || o->mode == MODE_SPPM2009;
    if (progressive && o->adaptive > 0)
        return error_set(err, "", 0, "--adaptive: not available with --mode %s, whose "
                                     "pixels are not means of independent samples",
                         mode_name(o->mode));
    if (o->mode == MODE_JENSEN1994 && o->cache_accuracy == 0)
        return error_set(err, "", 0, "--cache-accuracy: mode 1994 needs its irradiance "
                                     "cache, a > 0");
    /* Given, not set: options.c has filled its default in by now, and no preset or
     * --paper names it for these modes. */
    if (progressive && words->given(words->table, "--specular-spp") > 0)
        return error_set(err, "", 0, "--specular-spp: not available with --mode %s, whose "
                                     "pixels all take the same eye rays", mode_name(o->mode));
    if (o->specular_spp < o->spp) {
        char from[48];
        origin(o, words, "--spp", from, sizeof from);
        return error_set(err, "", 0, "--specular-spp %d: expected at least --spp (%d%s%s)",
                         o->specular_spp, o->spp, from[0] != '\0' ? ", " : "", from);
    }
    if (check_global_work_options(o, err) < 0)
        return -1;
    if (progressive && o->variance != NULL)
        return error_set(err, "", 0, "--variance: not available with --mode %s, whose "
                                     "pixels are not means of independent samples",
                         mode_name(o->mode));
    if (o->variance != NULL && o->spp < 2)
        return error_set(err, "", 0, "--variance: needs --spp >= 2 (one sample a pixel has "
                                     "no spread: its variance image would be all zero)");
    if (o->block_error != NULL && o->error == NULL)
        return error_set(err, "", 0, "--block-error: needs --error, whose bounds it sums "
                                     "over each block");
    if (o->block_error != NULL && o->has_crop)
        return error_set(err, "", 0, "--block-error: not with --crop, which cuts the blocks "
                                     "of the whole image at its edges (photon merge joins "
                                     "no block statements)");
    if (check_error_bound(o, words, err) < 0)
        return -1;
    return check_idle(o, words, err);
}
