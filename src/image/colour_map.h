/*
 * image/colour_map.h -- viridis, the perceptual colour map of the false-colour pictures
 * (colour_map.c): a number from 0 to 1 to an sRGB colour.
 */
#ifndef PHOTON_COLOUR_MAP_H
#define PHOTON_COLOUR_MAP_H

/* The control points: colour_map(k / (COLOUR_MAP_POINTS - 1)) is the k-th exactly. */
#define COLOUR_MAP_POINTS 18

/* The colour of t, R G B bytes into rgb[0..2]: t below 0 is 0's colour (dark blue-violet),
 * above 1 (or +Inf) 1's (yellow); NaN is the caller's to keep out. */
void colour_map(double t, unsigned char rgb[3]);

#endif
