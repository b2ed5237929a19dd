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

/* Where a mesh goes and what it is made of. */
struct obj_placement {
    int material;            /* index into the scene's materials, for every face        */
    double scale;            /* > 0 and finite: vertex p is placed at                   */
    struct vec3 translation; /*   scale * p + translation                              */
};

/* Adds every face of the OBJ file at path to scene as triangles. Returns 0, or -1 with
 * *err filled ("file:line: keyword: message"); on -1 the scene holds part of the mesh and
 * is for scene_free() only. */
int obj_import(struct scene *scene, const char *path, const struct obj_placement *place,
               struct error *err);

#endif
