/*
 * scene/reach_record.h -- what the readers have seen of a scene's reach so far: the record
 * struct scene holds and reach_note() fills, line by line (reach.h says what is checked
 * and why).
 *
 * A header of its own because the scene holds the record while reach.c reads the scene:
 * scene.h takes the record from here, reach.c takes the scene from scene.h, and neither
 * header includes the other.
 */
#ifndef PHOTON_REACH_RECORD_H
#define PHOTON_REACH_RECORD_H

#include <stddef.h>

#include "../base/error.h"

struct scene_reach {
    double reach;                /* the largest |coordinate| seen (primitive, light, camera) */
    char file[ERROR_FILE_MAX];   /* the line that reached it, for the message                */
    int line;
    size_t n_prims, n_lights;    /* primitives and lights counted so far                     */
    int camera_counted;
    char camera_file[ERROR_FILE_MAX]; /* the camera's line                                   */
    int camera_line;
};

#endif
