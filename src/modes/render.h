/*
 * modes/render.h -- the pixel loop every camera-driven mode shares.
 *
 * A pixel's value is the mean radiance over the pixel's square: camera rays through
 * stratified points of the pixel (a box filter; camera_sample), each estimated by the
 * mode. Sample s of pixel (x, y) draws every other random number of its path from
 * rng_stream(seed, STREAM_CAMERA, y * width + x, s), (x, y) in the whole image, so a
 * pixel's value depends on nothing but the scene, the settings and its place: a crop
 * equals the same window of the whole image, bit for bit.
 *
 * Samples are taken in sample passes: pass s adds sample s to every pixel of the window
 * that is still sampling. Each pixel's samples are summed in the order s = 0, 1, 2, ...,
 * so stopping after any pass gives exactly the image a render with that many samples
 * would give. Checkpoints (for --report) fall after passes 1, 2, 4, 8, ... and after the
 * last.
 *
 * Adaptive sampling (Jensen & Christensen 1994, Sec. 5: "each pixel has been sampled
 * adaptively based on the variance of each sample") is off when adaptive_error is 0, and
 * then every pixel takes every pass up to its target. When it is on, a pixel that has
 * taken n samples, n a power of two with min_spp <= n < spp (specular_spp where that
 * applies, below), takes no more once
 *     sqrt(s^2 / n) <= adaptive_error * max(m, ADAPTIVE_FLOOR),
 * m and s^2 = (sum of (y - m)^2) / (n - 1) being the mean and the sample variance of the
 * luminance y (vec3_luminance) of its n samples: the estimated standard error of its mean
 * is at most adaptive_error relative to the mean, or, for a pixel darker than the floor,
 * relative to the floor. A pixel whose samples are all equal (black, or a light seen
 * directly) has s^2 = 0 exactly and stops at min_spp (or spp, if less). Stopping only at
 * powers of two leaves each pixel's camera points stratified (camera_sample). The rule
 * reads nothing but the pixel's own samples, so the crop promise above still holds, and a
 * pixel that stops after n samples has exactly the value a render with spp = n gives it.
 *
 * Specular pixels. A pixel in which the camera sees a light through mirrors or glass
 * takes specular_spp samples instead of spp. The light's image after ideal specular
 * bounces (in a glass ball seen in a mirror ball, say) can be a speck far smaller than a
 * pixel and far brighter than the rest of it, which only the pixel's camera points find:
 * its noise falls only with more of them (src/modes/measured.md has the figures:
 * SPECULAR_SPP_FACTOR). Whether the camera sees one is decided
 * by probe rays (render.c: a 16 x 16 grid through the pixel, followed through every lobe
 * of each mirror or glass surface they meet, where a ray through its centre or a corner
 * meets one), not by its samples, so the number of samples does not depend on what they
 * found and the mean stays unbiased; a pixel with n samples still has exactly the value
 * a render with spp = n gives it. Through a thin lens the probes leave the lens's centre.
 */
#ifndef PHOTON_RENDER_H
#define PHOTON_RENDER_H

#include <stdint.h>
#include <time.h>

#include "../base/rng.h"
#include "../image/image.h"
#include "../scene/scene.h"
#include "render_counters.h"

#define MAX_SPP (1 << 20)    /* documented limit on samples per pixel */
#define DEFAULT_SPP 16       /* --spp when not given, for the camera-driven modes */
#define MAX_DEPTH_LIMIT 1000 /* documented limit on --max-depth */
/* The luminance below which adaptive sampling measures a pixel's error against this floor
 * instead of its mean. Radiance 1 shows as white at exposure 1 (display_encode), and one 8-bit
 * sRGB step near black is 1 / (255 * 12.92) = 3e-4 of it, so a pixel darker than 1e-3 is
 * within about three steps of black, where no one can see its relative error: without
 * the floor, nearly black pixels would spend samples on it. The floor is absolute, so it
 * assumes scenes whose radiance is meant to be seen at an exposure near 1, as ours are. */
#define ADAPTIVE_FLOOR 1e-3
#define ADAPTIVE_MIN_SPP 4 /* the command line's min_spp: the paper's "average of 4 samples
                              pr. pixel" is where its adaptive sampling settled            */
/* 1994's and 1996's --specular-spp is this many times --spp: the light's speck in the
 * glass ball seen in the mirror ball keeps its 16 x 16 block of the specular Cornell box
 * off the path tracer's at 64 samples and still at 256; 64 times as many bring it close
 * (src/modes/measured.md). */
#define SPECULAR_SPP_FACTOR 64

struct render_settings {
    uint64_t seed;
    int spp;            /* camera samples per pixel, 1..MAX_SPP: the most passes run      */
    double time_limit;  /* CPU seconds; > 0: no pass starts after it has passed           */
    int max_depth;      /* longest chain of bounces followed, 0..MAX_DEPTH_LIMIT          */
    int x0, y0, x1, y1; /* the window rendered, [x0, x1) x [y0, y1) of the whole image    */
    int progress;       /* whether to print a progress line on stderr                     */
    double adaptive_error; /* 0: adaptive sampling off; > 0 (finite): the stopping rule's
                              bound on each pixel's standard error, relative to its mean */
    int min_spp;        /* with adaptive_error > 0: the samples every pixel takes before
                           the rule applies, a power of two >= 2 (it needs a variance)  */
    int specular_spp;   /* when more than spp: the samples, in place of spp, of a pixel
                           in which the camera sees a light through mirrors or glass;
                           otherwise those take spp too                                  */
    double error_confidence; /* 0: no error image; else its confidence c, 0 < c < 1, with
                                spp >= ERROR_MIN_SPP and adaptive sampling off
                                (pixel_error.h); every pixel then takes at least
                                ERROR_MIN_SPP samples, whatever the time limit            */
    double target_error; /* 0: none; > 0 (with error_confidence): the passes end once every
                            block of image/error_image.h is within it, judged after pass
                            p >= ERROR_MIN_SPP whenever p is a multiple of the largest power
                            of two <= p / 8 (16, 18, ..., 32, 36, ...: the error image is
                            made about 8 times a doubling, and at most 1/8 more passes run
                            than were needed); counters then hold the blocks' tally        */
};

/* Radiance arriving at the camera along ray, estimated by a mode from its own state. */
/* A camera sample's uniforms for the first surface its path meets, beyond its points in
 * the pixel and on the lens (first_bounce_sample()): the two of the BRDF sample's
 * direction. */
struct first_bounce {
    double direction[2];
};

/* A mode's estimate of the radiance along a camera ray: rng is the sample's stream, and
 * first, NULL or the sample's stratified uniforms for the first surface the path meets,
 * which a mode may draw from instead of the stream (pt does). */
struct radiance_estimator {
    struct vec3 (*radiance)(const void *mode, struct ray ray, const struct first_bounce *first,
                            struct rng *rng, struct render_counters *counters);
    const void *mode; /* borrowed; passed back to radiance() */
    /* NULL, or called after each radiance() with the index of the pixel whose sample it
     * was, row-major in the window render_pixels() renders (rs's, with no error image),
     * the value the pixel took, and whether it counted (a non-finite one counts as
     * zero): for a mode that keeps more of a sample than its radiance (photons.c's
     * batches). */
    void (*sample_taken)(const void *mode, size_t pixel, struct vec3 value, int counted);
};

/* CPU seconds since start, a clock() reading: what every mode's timings count. */
static inline double cpu_seconds(clock_t start)
{
    return (double)(clock() - start) / CLOCKS_PER_SEC;
}

/* Whether n is 1, 2, 4, 8, ...: the passes after which a checkpoint is called. */
static inline int is_power_of_two(long n)
{
    return n > 0 && (n & (n - 1)) == 0;
}

/* The whole image's row-major index of pixel i of rs's window, in an image `width` wide:
 * what keys a pixel's random streams, so that a crop draws the numbers the whole does. */
static inline uint64_t image_pixel(const struct render_settings *rs, int width, size_t i)
{
    size_t window_width = (size_t)(rs->x1 - rs->x0); /* >= 1: a window is never empty */
    uint64_t x = (uint64_t)rs->x0 + i % window_width, y = (uint64_t)rs->y0 + i / window_width;
    return y * (uint64_t)width + x;
}

/* Called at each checkpoint with the current mean image (each pixel the mean of its own
 * samples) and the work done so far: photons emitted for photon passes; for camera modes
 * the samples per pixel, that is all samples taken in the window divided by its pixels,
 * rounded to the nearest integer (the passes run, when adaptive sampling is off). Returns
 * the CPU seconds it spent, which the render excludes from its own clock. */
struct checkpoint {
    double (*at)(void *context, const struct image *mean, long long work, double seconds);
    void *context;
};

/* What a render produces: the mean and, optionally, the variance of that mean and a bound
 * on its error. */
struct render_result {
    struct image *image;    /* owned: mean radiance over each pixel                       */
    struct image *variance; /* owned or NULL: per pixel and channel, the variance of the
                               mean, s^2 / n from the samples' own second moment, n the
                               pixel's own sample count (0 when n < 2); it treats the
                               stratified camera points as independent, so at edges it
                               is typically an over-estimate                               */
    struct image *error;    /* owned or NULL: with rs->error_confidence, each pixel's bound
                               on |image - truth| at that confidence (pixel_error.h;
                               2008, 2009: sppm_error.h)                                   */
    struct image *bias;     /* owned or NULL: the estimated bias b whose |b| error includes
                               (2008, 2009), adding linearly over a block (error_image.h);
                               NULL: error is all noise                                    */
    struct image *block_noise; /* owned or NULL: the bound on the noise of each block's
                               mean (image/error_image.h, stated_error), where the pixels'
                               noise is not independent (2008, 2009); NULL: it is      */
    struct image *block_bias; /* owned or NULL: the bias of each block's mean that its
                               bound includes (stated_error), where the mode states it
                               (2008, 2009); NULL: the sum of the pixels' bias         */
    double seconds;         /* CPU seconds rendering, checkpoint work excluded            */
};

/* Settings for the whole image of scene (finished): seed, spp and max_depth as given, no
 * time limit, no progress line, adaptive sampling off, no specular pixels' samples.
 * Callers change the window or the rest as they need. */
struct render_settings render_settings_whole(const struct scene *scene, uint64_t seed, int spp,
                                             int max_depth);

/* Camera sample s of pixel (x, y) of the whole image. The ray goes through point s of the
 * (0,2)-sequence in the pixel's square, digitally shifted by the pixel's own random word
 * from rng_stream(seed, STREAM_PIXEL, y * width + x, 0) (sequence02.h): each point is
 * uniform, and the first 1, 2, 4, ... samples of a pixel are stratified, which keeps the
 * light's outline and other edges from aliasing at low sample counts. Through a thin lens
 * (camera.h) the ray leaves the lens point given by Sobol's third and fourth dimensions
 * of point s, shifted by the stream's next word: stratified over the lens, and jointly
 * with the point in the pixel (sequence02_lens_point()). *rng becomes the
 * sample's stream, rng_stream(seed, STREAM_CAMERA, y * width + x, s), all the sample's
 * to use. */
struct ray camera_sample(const struct scene *scene, uint64_t seed, int x, int y, int s,
                         struct rng *rng);

/* The first-bounce uniforms of camera sample s of pixel (x, y): point s of a
 * (0,2)-sequence of the pixel's own, shuffled (sequence02_shuffled()) and shifted by words
 * of the pixel's stream after its camera points' two. Like the camera points, the first 1,
 * 2, 4, ... of a pixel are stratified, and so is each of pixel_error.h's batches;
 * shuffled, they do not follow the pixel points point for point, as the same index would
 * make them. The indirect light a surface gathers through its first bounce is much of a
 * path tracer's noise: on the Cornell box at 64 samples pt's relmse is 0.00185 with these
 * from the sample's stream, 0.00120 stratified (src/modes/measured.md). */
struct first_bounce first_bounce_sample(const struct scene *scene, uint64_t seed, int x, int y,
                                        int s);

/* Renders the settings' window of the scene's image (width x1 - x0, height y1 - y0),
 * each pixel taking up to rs->spp samples, or rs->specular_spp where the camera sees a
 * light through mirrors or glass (fewer by the adaptive rule or the time limit).
 * The caller guarantees min_spp as documented when adaptive_error > 0 (asserted).
 * want_variance: also fill result->variance. checkpoint may be NULL. */
struct render_result render_pixels(const struct scene *scene, const struct render_settings *rs,
                                   struct radiance_estimator estimator, int want_variance,
                                   const struct checkpoint *checkpoint,
                                   struct render_counters *counters);

void render_result_free(struct render_result *result);

/* Whether the target error is judged after pass p (rs->target_error above: p >=
 * ERROR_MIN_SPP and a multiple of the largest power of two <= p / 8); pt's sample passes
 * and 2008's and 2009's photon passes alike. */
int target_judged_after(long p);

struct stated_error;

/* The blocks of mean (rs's window) judged by what the mode states of its error
 * (image/error_image.h, blocks_within()) against rs->target_error, the tally into
 * counters' target fields; whether every block is within it. */
int target_tally(const struct image *mean, const struct stated_error *stated,
                 const struct render_settings *rs, struct render_counters *counters);

#endif
