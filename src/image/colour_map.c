/*
 * image/colour_map.c -- viridis (van der Walt and Smith, 2015), matplotlib's default
 * colour map, for the false-colour pictures (false_colour.h).
 *
 * Why viridis: its lightness rises evenly from one end to the other, so a larger value
 * always looks brighter and equal steps look equal (a rainbow map's bright yellow and
 * cyan bands invent edges that are not in the data); it stays ordered for the common
 * kinds of colour blindness and when printed in grey.
 *
 * The map is published as 256 sRGB colours (matplotlib's _viridis_data, in
 * lib/matplotlib/_cm_listed.py, released CC0). We keep 18 of them, entries 0, 15, 30,
 * ..., 255, as control points at t = k / 17, and interpolate linearly between them in the
 * encoded values, as a listed map's neighbours are. Measured against all 256 entries,
 * this stays within 5 of 255 levels (the most in blue near the yellow end, where the
 * map's blue dips), within 2 over most of the range.
 */
#include "colour_map.h"

#include <math.h>

/* _viridis_data[15 k], k = 0 .. 17, as published (sRGB-encoded, 0 to 1). */
static const double viridis[COLOUR_MAP_POINTS][3] = {
    {0.267004, 0.004874, 0.329415}, /*   0 */
    {0.281924, 0.089666, 0.412415}, /*  15 */
    {0.280255, 0.165693, 0.476498}, /*  30 */
    {0.263663, 0.237631, 0.518762}, /*  45 */
    {0.237441, 0.305202, 0.541921}, /*  60 */
    {0.208623, 0.367752, 0.552675}, /*  75 */
    {0.182256, 0.426184, 0.557120}, /*  90 */
    {0.159194, 0.482237, 0.558073}, /* 105 */
    {0.137770, 0.537492, 0.554906}, /* 120 */
    {0.121148, 0.592739, 0.544641}, /* 135 */
    {0.128087, 0.647749, 0.523491}, /* 150 */
    {0.180653, 0.701402, 0.488189}, /* 165 */
    {0.274149, 0.751988, 0.436601}, /* 180 */
    {0.395174, 0.797475, 0.367757}, /* 195 */
    {0.535621, 0.835785, 0.281908}, /* 210 */
    {0.688944, 0.865448, 0.182725}, /* 225 */
    {0.845561, 0.887322, 0.099702}, /* 240 */
    {0.993248, 0.906157, 0.143936}, /* 255 */
};

void colour_map(double t, unsigned char rgb[3])
{
    double position = fmax(0.0, fmin(1.0, t)) * (COLOUR_MAP_POINTS - 1);
    int k = (int)position; /* the control point below; the last interval holds t = 1 */
    if (k > COLOUR_MAP_POINTS - 2)
        k = COLOUR_MAP_POINTS - 2;
    double f = position - k;
    for (int c = 0; c < 3; c++) {
        double v = viridis[k][c] + f * (viridis[k + 1][c] - viridis[k][c]);
        rgb[c] = (unsigned char)floor(255.0 * v + 0.5);
    }
}
