/*
 * modes/photons_error.c -- the error image of `--mode photons` (photons_error.h).
 */
#include "photons_error.h"

#include <string.h>

#include "../base/alloc.h"
#include "pixel_error.h"

/* The photons' batches and the samples' are paired, one y_b each (photons_error.h). */
extern char batches_pair[PHOTON_BATCHES == ERROR_BATCHES ? 1 : -1];

void photons_error_create(struct photons_error *pe, const struct render_settings *rs,
                          int width, int height)
{
    kept_window_init(&pe->kept, rs, width, height, SPPM_PIXEL_MARGIN);
    size_t n = (size_t)pe->kept.width * (size_t)pe->kept.height;
    memset(&pe->sample, 0, sizeof pe->sample);
    pe->pixels = xcalloc(n, sizeof *pe->pixels, "photon batches");
    pe->sample_batches = xcalloc(3 * ERROR_BATCHES * n, sizeof *pe->sample_batches,
                                 "sample batches");
    pe->samples = xcalloc(n, sizeof *pe->samples, "photon batch samples");
}

static void add_batches(struct estimate_batches *to, struct vec3 weight,
                        const struct estimate_batches *from)
{
    for (int b = 0; b < PHOTON_BATCHES; b++) {
        to->disc[b] = vec3_add(to->disc[b], vec3_mul(weight, from->disc[b]));
        to->inner[b] = vec3_add(to->inner[b], vec3_mul(weight, from->inner[b]));
    }
}

void photons_error_add_estimate(struct photons_error *pe, struct vec3 beta,
                                const struct estimate_batches *batches)
{
    add_batches(&pe->sample, beta, batches);
}

void photons_error_sample_taken(struct photons_error *pe, size_t i, struct vec3 value,
                                int counted)
{
    if (counted)
        add_batches(&pe->pixels[i], vec3(1.0, 1.0, 1.0), &pe->sample);
    double v[3] = {value.x, value.y, value.z};
    error_batches_add(pe->sample_batches + 3 * ERROR_BATCHES * i, ERROR_BATCHES,
                      pe->samples[i], v, 3);
    pe->samples[i]++;
    memset(&pe->sample, 0, sizeof pe->sample);
}

/* c_b of kept pixel i (photons_error.h): the mean of its samples' pair of batches b mod h
 * (the h = k / 2 pairs of its k full batches of m) less the mean of the pairs; zero with
 * fewer than two pairs. */
static struct vec3 sample_deviation(const struct photons_error *pe, size_t i, int b)
{
    int n = pe->samples[i], m = error_batch_size(ERROR_BATCHES, n), h = n / m / 2;
    if (h < 2)
        return vec3_zero();
    const double *batch = pe->sample_batches + 3 * ERROR_BATCHES * i;
    double d[3];
    for (int c = 0; c < 3; c++) {
        double all = 0.0;
        for (int j = 0; j < 2 * h; j++)
            all += batch[3 * j + c];
        int pair = 2 * (b % h);
        d[c] = (batch[3 * pair + c] + batch[3 * (pair + 1) + c] - all / h) / (2 * m);
    }
    return vec3(d[0], d[1], d[2]);
}

/* Kept pixel i's batch b as 2009's pass b (photons_error.h): y_b = e + c_b + B P_b over
 * the disc and over the inner disc, e the pixel's mean less its photons' part. */
static void add_pixel_pass(const struct photons_error *pe, struct sppm_error *e, size_t i,
                           int b, struct vec3 mean)
{
    const struct estimate_batches *sum = &pe->pixels[i];
    double per_sample = 1.0 / pe->samples[i];
    struct vec3 photons = vec3_zero();
    for (int j = 0; j < PHOTON_BATCHES; j++)
        photons = vec3_add(photons, sum->disc[j]);
    struct vec3 seen = vec3_sub(mean, vec3_scale(photons, per_sample));
    double scale = PHOTON_BATCHES * per_sample;
    sppm_error_add_pass(e, i, vec3_add(seen, sample_deviation(pe, i, b)),
                        vec3_scale(sum->disc[b], scale), vec3_scale(sum->inner[b], scale));
}

void photons_error_result(const struct photons_error *pe, const struct image *kept_image,
                          struct render_result *result)
{
    const struct kept_window *k = &pe->kept;
    struct sppm_error e;
    sppm_error_create(&e, k, 0);
    for (int b = 0; b < PHOTON_BATCHES; b++) {
        for (int y = 0; y < k->height; y++)
            for (int x = 0; x < k->width; x++)
                add_pixel_pass(pe, &e, (size_t)y * (size_t)k->width + (size_t)x, b,
                               image_get(kept_image, x, y));
        sppm_error_pass_done(&e, b);
    }
    sppm_error_result(&e, k, PHOTON_BATCHES, result);
    sppm_error_free(&e);
}

void photons_error_free(struct photons_error *pe)
{
    xfree(pe->pixels);
    xfree(pe->sample_batches);
    xfree(pe->samples);
    memset(pe, 0, sizeof *pe);
}
