/*
 * modes/ppm_radius.h -- the initial radius R0 of a progressive estimate, shared by
 * --mode 2008 (each hit point's) and --mode 2009 (each pixel's): pixel footprints at the
 * surface, fitted to it (ppm_radius.c says how and why).
 */
#ifndef PHOTON_PPM_RADIUS_H
#define PHOTON_PPM_RADIUS_H

#include "progressive.h"
#include "surface.h"

/* R0 at surface s, seen at `distance` along its eye path: ps->radius if it is given; else
 * ps->footprints pixel footprints (the width a pixel covers at that distance), and with
 * ps->fit_radius shortened until the disc lies on the surface (with past_walls_only, as
 * 2009's disc coverage wants, only to clear walls the surface goes on past). Adds its wall
 * probes to counters->rays. */
double ppm_initial_radius(const struct scene *scene, const struct progressive_settings *ps,
                          int past_walls_only, struct render_counters *counters,
                          const struct surface *s, double distance);

#endif
