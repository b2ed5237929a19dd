/*
 * photon/photon.h -- the photon record: 20 bytes, as Jensen 1996 (Sec. 3) stores it.
 *
 * A photon is a position, a power and the direction it arrived from, each in as few
 * bytes as will do (the paper gives the 20 bytes, not their layout; this one follows
 * Jensen's book, Jensen 2001): the position as three floats, the power in Ward's RGBE
 * shared-exponent format (4 bytes), the direction as two angles of 256 steps each, plus
 * one byte for the kd-tree's split axis and one for flags. Only photon.c packs and
 * unpacks these bytes; everything else calls photon_pack() and the getters, which
 * compute in double. The two direction bytes hold whatever unit direction the map's mode
 * gives: the incoming direction wi in the 1996 and photons modes' maps, read by
 * photon_direction(); the surface normal where the photon landed in mode 1994's (its
 * record is position, normal, energy and a caustic bit, Jensen and Christensen 1994,
 * Sec. 3.3) and in 1996's records of precomputed irradiance, read by photon_normal().
 *
 * Accuracy of the round trip photon_pack() -> getters:
 *   position:  each coordinate rounded to the nearest float (relative error <= 2^-24);
 *   power:     each channel within max(R, G, B) / 255.5 of its value (rounded RGBE), for
 *              max(R, G, B) >= 2^-128; below that the error is at most 2^-136 watts;
 *   direction: within pi/510 + pi/256 radians (1.06 degrees) of the given direction.
 * The kd-tree that orders photons lives in kdtree.h.
 */
#ifndef PHOTON_PHOTON_H
#define PHOTON_PHOTON_H

#include "../base/vec3.h"

/* Flags: what kind of photon this is (Jensen 1996, Sec. 3 and Fig. 1). The tracer that
 * stores photons decides which bits it sets; shadow photons (Jensen and Christensen 1995)
 * only mark where a light is blocked, so that shadow rays are cast only where the
 * nearest photons disagree. */
#define PHOTON_DIRECT 1u   /* "D": first hit of a path straight from a light             */
#define PHOTON_CAUSTIC 2u  /* stored on a diffuse surface after specular bounces only    */
#define PHOTON_INDIRECT 4u /* "I": stored after at least one diffuse bounce              */
#define PHOTON_SHADOW 8u   /* "S": a later hit along a light ray, in the light's shadow  */
/* Not a kind: the side of its surface a photon arrived on, the back of the primitive
 * (against its geometric normal), as the tracer knew it exactly. The direction bytes
 * cannot say: rounded to 1.06 degrees, a photon grazing the inside of a sphere can read
 * as one from outside, and a curved surface turns the normal between a photon and the
 * point estimated (radiance_estimate, estimate.h). Bit 7, apart from the kinds. */
#define PHOTON_BACK 128u
/* Not a kind either: the photon's batch, its emission index modulo PHOTON_BATCHES, in
 * bits 4-6. The batches split a map into PHOTON_BATCHES independent maps (the photons of
 * one emitted path share one batch), each with 1 / PHOTON_BATCHES of the photons, whose
 * estimates' spread states the noise every pixel sharing the map shares
 * (estimate.h, struct estimate_batches). */
#define PHOTON_BATCHES 8
#define PHOTON_BATCH_SHIFT 4
#define PHOTON_BATCH_BITS (7u << PHOTON_BATCH_SHIFT)

/* The paper's 20 bytes per photon; photon.c alone packs and unpacks them. */
struct photon {
    float pos[3];             /* bytes 0-11: position (float only here)                      */
    unsigned char power[4];   /* 12-15: RGB power, Ward's RGBE: mantissas R, G, B, exponent */
    unsigned char theta, phi; /* 16-17: direction wi or normal (photon_pack), 256 steps each */
    unsigned char plane;      /* 18: split axis 0..2 of this kd-tree node, set by
                                 balance_kdtree(); 0 until then                            */
    unsigned char flags;      /* 19: PHOTON_DIRECT | PHOTON_CAUSTIC | ... bits              */
};
extern char photon_is_20_bytes[sizeof(struct photon) == 20 ? 1 : -1];

/* The bound on each channel of a photon's power that RGBE's exponent byte can hold:
 * 2^127 W, exactly, so that rounding the largest channel up keeps e <= 128. */
#define PHOTON_POWER_MAX 1.7014118346046923e38

/* Whether photon_pack() can store power: every channel in [0, PHOTON_POWER_MAX), so
 * neither NaN nor Inf. The tracer ends a photon that leaves this range (trace.c). */
int photon_power_fits(struct vec3 power);

/* Packs a photon. position: where it is stored (finite). power: its flux in watts per
 * channel, photon_power_fits(power) (asserted). direction: wi, pointing
 * AWAY from the surface, back towards where the photon came from (the opposite of the
 * direction it travelled), so that it goes to a BRDF beside wo as it is; finite and
 * non-zero, of any length. flags: PHOTON_* bits, at most 255. plane is set to 0. */
struct photon photon_pack(struct vec3 position, struct vec3 power, struct vec3 direction,
                          unsigned flags);

struct vec3 photon_position(const struct photon *p); /* pos[] converted to double      */
struct vec3 photon_power(const struct photon *p);    /* watts per channel, >= 0         */
/* Unit wi, away from the surface. The first call fills photon.c's sin/cos tables. */
struct vec3 photon_direction(const struct photon *p);
/* The unit surface normal where the photon landed, in a map whose records hold it in
 * place of wi (1994's photons; 1996's records of precomputed irradiance): the same
 * bytes, rounding and tables as photon_direction(), named for what they hold there. */
struct vec3 photon_normal(const struct photon *p);
/* The photon's batch, 0..PHOTON_BATCHES - 1 (PHOTON_BATCH_BITS). */
unsigned photon_batch(const struct photon *p);

#endif
