/*
 * scene/obj.h -- reading a Wavefront OBJ mesh into a scene as triangles (the `obj` scene
 * keyword). obj.c's opening comment lists what is read, what is ignored and what refused.
 */
#ifndef PHOTON_OBJ_H
#define PHOTON_OBJ_H

#include "../base/error.h"
#include "scene.h"

/* Documented limit on each of a file's vertices, normals and texture coordinates: 2^24
 * (400 MB of vertices), refused beyond as absurd input. */
#define OBJ_MAX_VERTICES (1 << 24)

/* Where a mesh goes and what it is made of (obj_unmoved() fills every field). */
struct obj_placement {
    int material;            /* index into the scene's materials: every face's, but those
                                after a `usemtl` naming a material of the scene         */
    double scale;            /* > 0 and finite: vertex p is placed at                   */
    struct vec3 translation; /*   scale * R p + translation, R the turn by             */
    double degrees;          /*   degrees in [-360, 360] (0: none) about                */
    struct vec3 axis;        /*   axis through the origin (not zero unless degrees is 0),
                                counter-clockwise seen from its tip; normals turn by R */
};

/* The placement that leaves a mesh where its file puts it, all of `material`: scale 1,
 * no turn, no translation. */
struct obj_placement obj_unmoved(int material);

/* Adds every face of the OBJ file at path to scene as triangles. Returns 0, or -1 with
 * *err filled ("file:line: keyword: message"); on -1 the scene holds part of the mesh and
 * is for scene_free() only. */
int obj_import(struct scene *scene, const char *path, const struct obj_placement *place,
               struct error *err);

#endif
