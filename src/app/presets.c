/*
 * app/presets.c -- the quality presets (presets.h).
 *
 * preview: a quick look at a scene. Each photon mode renders the 256 x 256 Cornell boxes
 *   (scenes/cornell.scene, scenes/cornell-specular.scene) in 3-6 CPU seconds and shows
 *   every effect of the scene without blotches; a first look, not a figure. 1994 and
 *   1996 take no more samples where the camera sees a light through a ball, which
 *   spares the probe rays that find those pixels (3-4 s on the specular box).
 * default: the defaults of options.c and the modes' headers (no words), chosen there.
 * reference: what makes a reference image. Where a mode states its error (pt, 2008,
 *   2009) it renders to a target: every 16 x 16 block's 95% bound within 1% of its mean (the
 *   consistency rule is 3%, and the bound is 2-12 times the error, reference/suite.md's
 *   calibration), with a cap on the samples (passes) so that a scene where the bound
 *   cannot get there still ends, naming the blocks that missed. pt reaches it on the
 *   Cornell box at 2,048 samples (170 CPU s), where reference/cornell-pt.pfm took 4,096
 *   (360 s); its cap is 16 times that. 2008's and 2009's caps are 4 times the 576 and
 *   2,048 passes they took before, since their bounds are loose where the direct light is
 *   sampled (5-12 times the error) and where discs meet curved walls.
 *   The other photon modes converge further than their defaults at a few times their time:
 *   1994 twice the light rays and gather rays (the worst 16 x 16 block 2.8% -> 1.5%);
 *   1996 the same and 2 x --spp, since its relmse at the default samples is the
 *   camera's noise;
 *   photons 40 x the photons and 4 x the photons an estimate.
 * The measured seconds and errors of each row are in README (Presets);
 * scripts/presets.sh measures them again. A list names only options its mode takes.
 */
#include "presets.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

#include "option_values.h"

struct preset {
    enum mode mode;
    enum quality quality;
    const char *words; /* option words, one space apart */
};

static const struct preset presets[] = {
    {MODE_DIRECT, QUALITY_PREVIEW, "--spp 4"},
    {MODE_DIRECT, QUALITY_REFERENCE, "--spp 1024"},
    {MODE_PT, QUALITY_PREVIEW, "--spp 4"},
    {MODE_PT, QUALITY_REFERENCE, "--target-error 0.01 --spp 65536"},
    {MODE_PHOTONS, QUALITY_PREVIEW, "--spp 4"},
    {MODE_PHOTONS, QUALITY_REFERENCE, "--photons 8000000 --gather 400"},
    {MODE_JENSEN1994, QUALITY_PREVIEW,
     "--photons 200000 --gather-rays 64 --cache-accuracy 0.3 --spp 8 --specular-spp 8"},
    {MODE_JENSEN1994, QUALITY_REFERENCE, "--photons 8000000 --gather-rays 1024"},
    {MODE_JENSEN1996, QUALITY_PREVIEW,
     "--photons 200000 --caustic-photons 50000 --gather-rays 32 --cache-accuracy 0.3 "
     "--spp 8 --specular-spp 8"},
    {MODE_JENSEN1996, QUALITY_REFERENCE,
     "--photons 8000000 --caustic-photons 2000000 --gather-rays 1024 --spp 256 "
     "--specular-spp 8192"},
    {MODE_PPM2008, QUALITY_PREVIEW, "--passes 8 --spp 4"},
    {MODE_PPM2008, QUALITY_REFERENCE, "--target-error 0.01 --passes 2304"},
    {MODE_SPPM2009, QUALITY_PREVIEW, "--passes 16"},
    {MODE_SPPM2009, QUALITY_REFERENCE, "--target-error 0.01 --passes 8192"},
};

const char *quality_name(enum quality quality)
{
    switch (quality) {
    case QUALITY_PREVIEW:
        return "preview";
    case QUALITY_DEFAULT:
        return "default";
    case QUALITY_REFERENCE:
        return "reference";
    }
    return "?";
}

int read_quality(const char *text, enum quality *quality, struct error *err)
{
    static const enum quality qualities[] = {QUALITY_PREVIEW, QUALITY_DEFAULT,
                                             QUALITY_REFERENCE};
    for (size_t i = 0; text != NULL && i < sizeof qualities / sizeof qualities[0]; i++)
        if (strcmp(text, quality_name(qualities[i])) == 0) {
            *quality = qualities[i];
            return 0;
        }
    return error_set(err, "", 0,
                     "--quality: unknown quality '%s' (available: preview, default, reference)",
                     text != NULL ? text : "nothing");
}

/* --paper: the options that turn a mode's departures from its paper off (src/modes/
 * README.md lists each, why, and what it measured): each departure's --no-NAME, or the
 * paper's value of an option that is a number (--footprints 1), the rule at options.c's
 * enum option_kind. A mode not named has none with a switch. Beyond these words, --paper
 * gives the specular pixels --spp samples (options.c), since --specular-spp's default is a
 * multiple of --spp. Not here: --adaptive, whose threshold is not specified by the paper
 * (src/modes/README.md says why it stays off); and --caustic-radius-fraction, a fraction
 * of the maximum radius that --no-max-radius takes away. */
static const struct {
    enum mode mode;
    const char *words;
} as_written[] = {
    {MODE_PHOTONS, "--no-exclude-rim-photon --no-max-radius"},
    {MODE_JENSEN1994, "--no-exclude-rim-photon --no-max-radius --no-both-lobes "
                       "--no-glossy-photons --no-lobe-lights --no-bounded-reach "
                       "--no-gradient-limit --no-precomputed-irradiance"},
    {MODE_JENSEN1996, "--no-exclude-rim-photon --no-max-radius --no-shadow-rays "
                       "--no-precomputed-irradiance --no-disc-coverage --no-both-lobes "
                       "--no-glossy-corner --no-corner-photons --no-bounded-reach "
                       "--no-gradient-limit"},
    {MODE_PPM2008, "--no-direct-light-samples --footprints 1 --no-caustic-footprints "
                    "--no-fit-radius --no-merge-hit-points --no-resample-emission "
                    "--no-facing-test --no-turn-photon-directions"},
    {MODE_SPPM2009, "--no-direct-light-samples --footprints 1 --no-fit-radius "
                     "--no-disc-coverage --no-turn-photon-directions "
                     "--no-follow-glossy-lobes"},
};

/* Splits words, one space apart, into *out. */
static void split_words(const char *words, struct preset_words *out)
{
    assert(strlen(words) < sizeof out->text); /* the tables' lists are short */
    strcpy(out->text, words);
    out->n_words = 0;
    for (char *w = strtok(out->text, " "); w != NULL; w = strtok(NULL, " ")) {
        assert(out->n_words < PRESET_MAX_WORDS);
        out->word[out->n_words++] = w;
    }
}

void preset_words(enum mode mode, enum quality quality, struct preset_words *out)
{
    const char *words = "";
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; i++)
        if (presets[i].mode == mode && presets[i].quality == quality)
            words = presets[i].words;
    split_words(words, out);
}

void paper_words(enum mode mode, int paper, struct preset_words *out)
{
    const char *words = "";
    for (size_t i = 0; paper && i < sizeof as_written / sizeof as_written[0]; i++)
        if (as_written[i].mode == mode)
            words = as_written[i].words;
    split_words(words, out);
}

void print_presets(enum help_format format, int only)
{
    char head[64];
    help_section(format, "quality presets (--quality NAME; default: the defaults above; the "
                         "options given\non the command line win over the preset's, wherever "
                         "they stand)");
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; i++) {
        if (only >= 0 && presets[i].mode != (enum mode)only)
            continue;
        snprintf(head, sizeof head, "  --mode %-7s %-9s  ", mode_name(presets[i].mode),
                 quality_name(presets[i].quality));
        help_row(format, head, presets[i].words);
    }
    help_section(format, "--paper (the options it stands for, before the command line's; and "
                         "the specular\npixels take --spp samples)");
    for (size_t i = 0; i < sizeof as_written / sizeof as_written[0]; i++) {
        if (only >= 0 && as_written[i].mode != (enum mode)only)
            continue;
        snprintf(head, sizeof head, "  --mode %-7s ", mode_name(as_written[i].mode));
        help_row(format, head, as_written[i].words);
    }
}
