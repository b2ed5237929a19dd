/*
 * app/work_file.h -- the file of a render's global work: --save-photons writes it,
 * --load-photons reads it (photon/global_work.h says what the work is).
 *
 * Every tile of an image repeats its mode's global work (the photon maps, 1994's
 * illumination maps, and in 1994 and 1996 the irradiance cache's pre-pass over the whole
 * image); saved once and loaded by each tile, it is done once. The file is binary; every
 * number is little-endian whatever the machine, and written byte by byte (base/binary.h),
 * so a file is the same from every compiler and machine and is read on any of them:
 *
 *   offset  bytes     field
 *   0       8         magic "photonGW" (Global Work)
 *   8       4         version, WORK_FILE_VERSION
 *   12      8         hash: FNV-1a 64 of the scene's lines and the options that change
 *                     pixels, as a tile's record keeps it (app/tile.h)
 *   20      4         number of maps M, in the order the mode gives (photon/global_work.h)
 *   then M maps, each:
 *           1         1 when the map exists, 0 when the scene needs none (nothing more)
 *           8         N, its photons
 *           20 N      photons 1..N in the kd-tree's heap order, as they sit in memory
 *                     (photon.h): x, y, z as the bits of IEEE 754 floats, then power[4],
 *                     theta, phi, plane, flags, one byte each
 *   8                 number of irradiance-cache records R (0 for mode photons)
 *   224 R             records, 28 doubles each as the bits of IEEE 754 doubles:
 *                     p, n, E (3 each), R (1), grad_r[0..2], grad_t[0..2] (3 each)
 *   1                 1 when illumination maps follow (1994 with --irradiance-store
 *                     illumination), 0 when not (nothing more)
 *   ...               the illumination maps, in the layout photon/illumination_map.h
 *                     draws (illumination_map.c alone knows their insides)
 *   8                 checksum: FNV-1a 64 of every byte before it
 *
 * and nothing after. Every value is checked for its range as it is read, not only the
 * checksum (which anyone can compute for a file made by hand): a photon's position is
 * finite, its flags one photon kind (with any side and batch bits), its power at most WORK_PHOTON_POWER_MAX in each
 * channel; a record's position, irradiance and gradients are finite, its irradiance not
 * negative, its normal of unit length, its radius positive; an illumination map's
 * irradiances are finite and not negative. The writer refuses work outside the same
 * ranges, so a file photon saves, it loads. The maps are not balanced again on reading: each is checked
 * (kdtree_check) and used node for node, the records are added to the cache in the
 * order written, and the illumination maps come back element for element, so a render
 * that loads the file renders the very bits of one that made the work itself.
 *
 * Versions: 1 had no illumination maps (and no byte saying so); 2 adds them; 3 adds the
 * photon's side, PHOTON_BACK (2's photons would all read as arrived on the front).
 */
#ifndef PHOTON_WORK_FILE_H
#define PHOTON_WORK_FILE_H

#include <stdint.h>

#include "../base/error.h"
#include "../photon/global_work.h"

#define WORK_FILE_MAGIC "photonGW" /* 8 bytes, no terminating zero in the file */
#define WORK_FILE_VERSION 3

/* The most a photon in the file may carry, in watts per channel: 2^110, some 1.3e33. A
 * scene's lights give at most MAX_LIGHT_POWER (1e30, scene/scene.h) per channel in all;
 * a photon leaves a light with at most 1 / 0.0722 of that (a light picked by its
 * luminance, vec3.h, that is blue alone) and a BRDF weight above 1 (photon/trace.c) may
 * raise it about 90 times more. A photon of 1e37 W is no render's. */
#define WORK_PHOTON_POWER_MAX 1.298074214633707e33

/* Writes work (full) with hash to name, whole or not at all (output_open). -1 with *err
 * filled when it cannot be written, or (a failed write, nothing written) when a value is
 * out of the ranges above. */
int work_file_write(const char *name, uint64_t hash, const struct global_work *work,
                    struct error *err);

/* Reads name into *work (empty; the caller frees it with global_work_free() in every
 * case). -1 with *err ("FILE: message") when the file cannot be opened, is not such a
 * file, is of another version, was saved with another hash (another scene, mode, seed or
 * setting), is truncated or damaged (checksum), has bytes after its end, or holds a map
 * that is not a balanced kd-tree, or a value out of its range (above). */
int work_file_read(const char *name, uint64_t hash, struct global_work *work,
                   struct error *err);

#endif
