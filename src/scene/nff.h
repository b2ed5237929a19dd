/*
 * scene/nff.h -- reading Eric Haines' Neutral File Format (NFF), the output of the Standard
 * Procedural Databases (../shared/spd/), into a scene; and the polygon triangulation that
 * the NFF and OBJ readers share.
 *
 * nff.c's opening comment states exactly how NFF's entities become our camera, lights,
 * materials and primitives (README, "NFF files", copies it).
 */
#ifndef PHOTON_NFF_H
#define PHOTON_NFF_H

#include "../base/error.h"
#include "scene.h"

/* Documented limit on the vertices of one polygon (NFF `p`/`pp`, OBJ `f`): ear clipping
 * costs O(n^2) per polygon, and real polygons have far fewer (SPD's largest has 144). */
#define MAX_POLYGON_VERTICES 10000

/* Reads the NFF file at path into a new scene: camera, image size, background, materials,
 * lights and primitives. NULL with *err filled ("file:line: keyword: message") on bad
 * input; the scene is ready for scene_finish(). */
struct scene *nff_load(const char *path, struct error *err);

/* Adds the NFF file's contents to scene (the `nff FILE` scene keyword): its view replaces
 * the scene's camera and image size, its `b` the background. Returns 0, or -1 with *err
 * filled; on -1 the scene holds part of the file and is for scene_free() only. */
int nff_import(struct scene *scene, const char *path, struct error *err);

/* Splits the polygon v[0 .. n-1] (3 <= n <= MAX_POLYGON_VERTICES, in either winding) into
 * n - 2 triangles by ear clipping in its plane (the plane of Newell's normal), which handles
 * concave polygons. Writes the triangles' corner indices to triangles[0 .. 3(n-2) - 1], each
 * triangle in the polygon's own winding, so each faces the polygon's front side. For a simple
 * polygon the triangles tile it exactly; a self-intersecting or zero-area one still gets
 * n - 2 triangles (some may overlap or have no area), never an error. */
void polygon_triangulate(const struct vec3 *v, int n, int *triangles);

#endif
