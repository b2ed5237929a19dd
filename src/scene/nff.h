/*
 * scene/nff.h -- reading Eric Haines' Neutral File Format (NFF), the output of the Standard
 * Procedural Databases (SPD; a few of its files are in tests/data/spd/), into a scene.
 *
 * nff.c's opening comment states exactly how NFF's entities become our camera, lights,
 * materials and primitives (README, "Scene files", in short).
 */
#ifndef PHOTON_NFF_H
#define PHOTON_NFF_H

#include "../base/error.h"
#include "scene.h"

/* Reads the NFF file at path into a new scene: camera, image size, background, materials,
 * lights and primitives. NULL with *err filled ("file:line: keyword: message") on bad
 * input; the scene is ready for scene_finish(). */
struct scene *nff_load(const char *path, struct error *err);

/* Adds the NFF file's contents to scene (the `nff FILE` scene keyword): its view replaces
 * the scene's camera and image size, its `b` the background. Returns 0, or -1 with *err
 * filled; on -1 the scene holds part of the file and is for scene_free() only. */
int nff_import(struct scene *scene, const char *path, struct error *err);

#endif
