/*
 * app/probe.h -- `photon probe`: irradiance sampled along a line, the way Jensen and
 * Christensen 1994 compare their irradiance stores with an exact solution (Fig. 7-8).
 *
 *   photon probe SCENE --line X0 Y0 Z0 X1 Y1 Z1 --samples N -o FILE.csv
 *                [--normal NX NY NZ] [--photons N] [--gather N] [--differential R] [--seed S]
 *
 * One CSV row per sample point p_i = a + (b - a) i / (N - 1) (the line should lie on a
 * surface facing --normal, default +y), with the header
 *   x,y,z,exact_direct,exact_caustic,caustic_photons,caustic_photons_unchecked,all_photons,
 *   caustic_illumination
 *   exact_direct        irradiance from the point lights (shadow-tested), exact; none when
 *                       the scene has an area light (no closed form here)
 *   exact_caustic       irradiance of one ideal reflection off planar mirrors (each point
 *                       light's image source through each mirror quad or triangle it
 *                       reaches, Fig. 7's caustic), exact for point lights; none as above
 *   caustic_photons     mode 1994's caustic estimate (CP photons, differential checking)
 *   caustic_photons_unchecked  the same without differential checking
 *   all_photons         the general estimate (all photons, differential checking)
 *   caustic_illumination  the caustic illumination map (CI) of the surface under the
 *                       point, when it has one (quads and spheres), from the same light
 *                       rays with --irradiance-store illumination; else none
 * "none" (CSV_NONE, csv.h) is the cell of a column with no value at the point, which
 * `photon plot` leaves out of that column's line and counts in its legend.
 * Irradiance is luminance (vec3_luminance) in W / m^2. The photon map is mode 1994's
 * (jensen1994.h) with --photons light rays and --gather photons per estimate (default 200,
 * the paper's Fig. 8). Bad input exits 2 with a message and writes nothing.
 */
#ifndef PHOTON_PROBE_H
#define PHOTON_PROBE_H

#include "../base/option_equals.h"

/* argv[0] is "probe". Returns the exit status: 0, 1 (a failed write) or 2 (bad input). */
int probe_command(int argc, char **argv);

/* Its options, for --NAME=VALUE (app/commands.h); a NULL name ends them. */
extern const struct option_arity probe_options[];

#endif
