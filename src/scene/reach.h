/*
 * scene/reach.h -- how far a scene reaches from the origin, against the range that double
 * precision and the tracer resolve; scenes outside it are refused where they are read.
 *
 * Why these limits (README: Scene files; the renders that test them, a 1 W point light over
 * a white floor with a blocker between them: src/modes/measured.md): a hit point is resolved
 * to about 2^-52 of its distance from the origin (a sphere's to 2^-52 of its radius), and a
 * spawned ray starts RAY_OFFSET_REL x max(1, |p|) = 1e-9 x max(1, |p|) off its surface. So:
 *   - a scene may reach at most REACH_MAX_RATIO = 2^40 (1.1e12) times the camera's distance
 *     to its look-at point from the origin: there a point is resolved to 2^-12 of that
 *     distance, and further out the picture moves, then hit points snap together;
 *   - the camera's distance to its look-at point must be at least REACH_MIN_CAMERA = 1e-6,
 *     above which a blocker just over a floor still casts its shadow.
 * The reach counts every primitive's box, every point light and the camera; what has been
 * counted so far is the scene's own record (reach_record.h).
 */
#ifndef PHOTON_REACH_H
#define PHOTON_REACH_H

#include "../base/error.h"

#define REACH_MAX_RATIO 1099511627776.0 /* 2^40: see above */
#define REACH_MIN_CAMERA 1e-6           /* 1000 x the smallest ray offset, 1e-9       */

struct scene;

/* Counts what file:line added to the scene since the last call; readers call it after
 * each line. */
void reach_note(struct scene *scene, const char *file, int line);

/* -1 with *err ("file:line: ...", the line that reached furthest, or the camera's) when
 * the scene reaches beyond REACH_MAX_RATIO times the camera's distance, or that distance
 * is below REACH_MIN_CAMERA. The scene has a camera. */
int reach_check(const struct scene *scene, struct error *err);

#endif
