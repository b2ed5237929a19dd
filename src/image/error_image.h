/*
 * image/error_image.h -- what an error image states of a block of pixels and of the
 * whole image: the bounds --stats reports and --target-error renders to.
 *
 * An error image holds, per pixel and channel, a bound B on |pixel - truth| at a
 * confidence c: B = |b| + z_c sigma, b the pixel's estimated bias (0 where the mode's
 * mean is unbiased, pt: modes/pixel_error.h; 2008's and 2009's density estimates:
 * modes/sppm_error.h, which hands b over as an image of its own), sigma the standard
 * error of the pixel's mean. A pixel's luminance (vec3_luminance's weights w) is bounded
 * by sum_c w_c B_c, its channels being one estimate's and so correlated; the mean of a
 * block of n pixels by
 *     B_block = |sum over the pixels of w.b| / n + N_block,
 * the biases adding linearly, with their signs, and N_block the bound on the noise of
 * the block's mean at the same confidence (a mode may state the block's bias itself in
 * place of the sum, as 2008 and 2009 do: stated_error's block_bias): where the pixels'
 * noise is independent (pt),
 *     N_block = sqrt(sum over the pixels of (sum_c w_c (B_c - |b_c|))^2) / n,
 * their noise adding in quadrature; where it is not (2008's and 2009's pixels share the photons of
 * discs a few pixels wide), the mode states N_block itself, an image of one pixel a
 * block (stated_error's block_noise). A block is
 * within E when B_block <= E times its mean luminance; blocks whose mean luminance is
 * below ERROR_DARK_FLOOR are left out, as dark as the adaptive rule's floor
 * (modes/render.h), where no one sees a relative error. The blocks are the squares of
 * ERROR_BLOCK pixels whose corners lie at multiples of ERROR_BLOCK in the whole image, cut
 * by the image's edges: a crop's blocks are the whole image's, where it holds them whole.
 */
#ifndef PHOTON_ERROR_IMAGE_H
#define PHOTON_ERROR_IMAGE_H

#include "image.h"

#define ERROR_BLOCK 16         /* the side of the blocks --stats and --target-error judge */
#define ERROR_DARK_FLOOR 1e-3  /* mean luminance below which a block is left out          */

/* What a mode states of its image's error (render_result's error, bias, block_noise),
 * for a window whose top left pixel is (x0, y0) of the whole image. */
struct stated_error {
    const struct image *error;       /* per pixel and channel, the bound B                 */
    const struct image *bias;        /* NULL (none), or the signed b whose |b| B includes  */
    const struct image *block_noise; /* NULL (the pixels' noise is independent), or per
                                        block of the grid the window meets, row-major from
                                        the block of its top left pixel
                                        (error_block_grid()), N_block per channel        */
    const struct image *block_bias;  /* NULL (a block's bias is its pixels' b summed), or
                                        per block as block_noise, the signed bias of the
                                        block's mean that its bound includes instead    */
};

/* The blocks of the grid above that a window of width x height pixels at (x0, y0) of the
 * whole image meets: columns x rows of them. */
void error_block_grid(int x0, int y0, int width, int height, int *columns, int *rows);

/* The pixels [u0, u1) x [v0, v1) of that window in its block (column, row). */
void error_block_window(int x0, int y0, int width, int height, int column, int row, int *u0,
                        int *v0, int *u1, int *v1);

/* How many of the blocks of image (image's top left pixel is (x0, y0) of the whole
 * image; stated's images of its size) are judged, dark ones aside, and how many of
 * those are within e; the first block (in rows from the top) that is not, by its top
 * left pixel in the whole image, or (-1, -1). */
struct block_count {
    int n_blocks, within;
    int missed_x, missed_y;
};
struct block_count blocks_within(const struct image *image, const struct stated_error *stated,
                                 int x0, int y0, double e);

/* The block statement (--block-error): per block of the grid above that the window of
 * image at (x0, y0) meets (error_block_grid(), one pixel a block), per channel, the bound
 * on |block mean - truth| at stated's confidence, |sum of the pixels' b| / n + N_block
 * (the rule above, per channel: N_block from stated's block_noise, else its pixels' noise
 * in quadrature). A block's luminance is bounded by sum_c w_c of its channels' bounds,
 * which is what photon compare reads from it (--test-block-error). Owned by the caller. */
struct image *block_error_image(const struct image *image, const struct stated_error *stated,
                                int x0, int y0);

/* How an error image's statement held against a reference (ERROR.md's words), block by
 * block (the grid above, of the whole image the images are): a block's statement holds
 * when |mean a - mean b| of its luminance is at most sqrt(B^2 + (z_c sigma_b)^2), B its
 * bound by the rule above and sigma_b the reference's block standard error (0 without
 * its variance), so that the reference's own noise is not counted against a. Blocks whose
 * reference mean is below ERROR_DARK_FLOOR are left out. The images hold variances of
 * the pixels' means (an error image's (B / z_c)^2, as compare reads it). */
struct bound_check {
    int n_blocks, covered; /* blocks judged and those whose statement held            */
    double median_ratio;   /* the median over blocks of B / |mean a - mean b| (+Inf for
                              equal means and B > 0; blocks with both 0 are left out);
                              an exact normal bound at 0.95 gives 2.91; -1 for none    */
    double rms_ratio;      /* rms(B) / rms(mean a - mean b) over the blocks; an exact
                              bound gives z_c, 1.96 at 0.95; -1 for none               */
};
struct bound_check bound_check(const struct image *a, const struct image *var_a,
                               const struct image *b, const struct image *var_b, double z);

/* What --stats says of an error image at confidence c (image at (x0, y0) and stated as
 * above). */
struct error_summary {
    double relmse;       /* estimated: the mean over pixels and channels of
                            (b^2 + sigma^2) / (pixel^2 + 1e-2), sigma = (B - |b|) / z_c:
                            what `photon compare`'s relmse against the truth would be, in
                            expectation                                                */
    int n_blocks;        /* blocks at or above ERROR_DARK_FLOOR                          */
    int within_1, within_3; /* of them, those within 1% and 3% of their mean             */
};
struct error_summary error_summary(const struct image *image, const struct stated_error *stated,
                                   double confidence, int x0, int y0);

#endif
