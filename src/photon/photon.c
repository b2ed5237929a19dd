/*
 * photon/photon.c -- packing and unpacking the 20-byte photon (Jensen 1996, Sec. 3).
 *
 * Power: Ward's RGBE ("Real pixels", Graphics Gems II). With v = max(R, G, B) written
 * v = m 2^e, m in [0.5, 1) (frexp), each channel c is stored as the byte round(c 2^(8-e))
 * and e as the byte e + RGBE_BIAS. Ward truncates; rounding to nearest halves the error
 * and makes decoding a plain c 2^(e-8). The largest byte is then round(m 256) in
 * [128, 256]; 256 does not fit, so then e grows by one and the bytes are recomputed
 * (the largest becomes 128). Each channel's error is at most half a step, 2^(e-9), and
 * v >= 127.75 * 2^(e-8), so the error is at most v / 255.5 on every channel, however
 * strongly coloured. Range: v < 2^127 = PHOTON_POWER_MAX (asserted; photon.h). Below
 * 2^-128, e stays at -127 and the bytes lose precision gradually (absolute error <=
 * 2^-136); all-zero power packs to four zero bytes and decodes to exact zero.
 *
 * Direction: theta = angle from +z in [0, pi], 256 steps that include both poles
 * (theta = i pi / 255, error <= pi / 510); phi = angle about z from +x in [0, 2 pi), 256
 * steps (phi = j 2 pi / 256, error <= pi / 256, which moves the direction by at most
 * sin(theta) pi / 256). Both are rounded to nearest; by the triangle inequality the
 * decoded direction is within pi/510 + pi/256 radians (1.06 degrees) of the true one.
 * Angles come from atan2, which is well conditioned everywhere (acos is not near the
 * poles), and need no normalisation. Decoding reads sin/cos tables filled from libm on
 * first use (Jensen's photonmap.cc fills the same tables in its constructor).
 */
#include "photon.h"

#include <assert.h>

#define RGBE_BIAS 127          /* exponent byte = e + 127, e in [-127, 128]             */
#define RGBE_E_MIN (-127)      /* smaller exponents clamp here: gradual underflow        */
#define DIRECTION_STEPS 256    /* Jensen 1996: one byte per angle                       */

char photon_is_20_bytes[sizeof(struct photon) == 20 ? 1 : -1];

/* The decoding tables: theta_i = i pi / 255, phi_j = j 2 pi / 256. */
struct direction_tables {
    int filled;
    double cos_theta[DIRECTION_STEPS], sin_theta[DIRECTION_STEPS];
    double cos_phi[DIRECTION_STEPS], sin_phi[DIRECTION_STEPS];
};
static struct direction_tables tables;

static void fill_direction_tables(void)
{
    for (int i = 0; i < DIRECTION_STEPS; i++) {
        double theta = i * (PI / (DIRECTION_STEPS - 1));
        double phi = i * (2.0 * PI / DIRECTION_STEPS);
        tables.cos_theta[i] = cos(theta);
        tables.sin_theta[i] = sin(theta);
        tables.cos_phi[i] = cos(phi);
        tables.sin_phi[i] = sin(phi);
    }
    tables.filled = 1;
}

/* Byte round(c * scale) for 0 <= c * scale < 255.5 (the caller guarantees the bound). */
static unsigned char rounded_byte(double c, double scale)
{
    return (unsigned char)(c * scale + 0.5);
}

int photon_power_fits(struct vec3 power)
{
    return power.x >= 0 && power.x < PHOTON_POWER_MAX && power.y >= 0 &&
           power.y < PHOTON_POWER_MAX && power.z >= 0 && power.z < PHOTON_POWER_MAX;
}

static void pack_power(struct vec3 power, unsigned char rgbe[4])
{
    assert(photon_power_fits(power)); /* the caller's guarantee (photon.h) */
    double v = vec3_max_component(power);
    int e = 0;
    frexp(v, &e);                /* v = m 2^e, m in [0.5, 1) */
    if (v == 0 || e < RGBE_E_MIN)
        e = RGBE_E_MIN;
    if (v * ldexp(1.0, 8 - e) + 0.5 >= 256.0)
        e++;                     /* round(m 256) = 256: one more bit of exponent */
    double scale = ldexp(1.0, 8 - e);
    rgbe[0] = rounded_byte(power.x, scale);
    rgbe[1] = rounded_byte(power.y, scale);
    rgbe[2] = rounded_byte(power.z, scale);
    rgbe[3] = (unsigned char)(e + RGBE_BIAS);
}

/* The index of the multiple of step nearest to angle (halves round up). */
static long nearest_step(double angle, double step)
{
    return (long)floor(angle / step + 0.5);
}

struct photon photon_pack(struct vec3 position, struct vec3 power, struct vec3 direction,
                          unsigned flags)
{
    assert(vec3_is_finite(position) && vec3_is_finite(direction));
    assert(vec3_max_abs(direction) > 0 && flags <= 255);
    struct photon p;
    p.pos[0] = (float)position.x;
    p.pos[1] = (float)position.y;
    p.pos[2] = (float)position.z;
    pack_power(power, p.power);
    double theta = atan2(hypot(direction.x, direction.y), direction.z); /* [0, pi]   */
    double phi = atan2(direction.y, direction.x);                       /* [-pi, pi] */
    p.theta = (unsigned char)nearest_step(theta, PI / (DIRECTION_STEPS - 1));
    /* phi / step lies in [-128, 128]; adding 256 before the modulus keeps it positive */
    long j = nearest_step(phi, 2.0 * PI / DIRECTION_STEPS) + DIRECTION_STEPS;
    p.phi = (unsigned char)(j % DIRECTION_STEPS);
    p.plane = 0;
    p.flags = (unsigned char)flags;
    return p;
}

struct vec3 photon_position(const struct photon *p)
{
    return vec3(p->pos[0], p->pos[1], p->pos[2]);
}

struct vec3 photon_power(const struct photon *p)
{
    double scale = ldexp(1.0, (int)p->power[3] - RGBE_BIAS - 8); /* 2^(e - 8) */
    return vec3(p->power[0] * scale, p->power[1] * scale, p->power[2] * scale);
}

struct vec3 photon_direction(const struct photon *p)
{
    if (!tables.filled)
        fill_direction_tables();
    double sin_theta = tables.sin_theta[p->theta];
    return vec3(sin_theta * tables.cos_phi[p->phi], sin_theta * tables.sin_phi[p->phi],
                tables.cos_theta[p->theta]);
}

struct vec3 photon_normal(const struct photon *p)
{
    return photon_direction(p); /* the bytes are one; what they mean is the map's */
}

unsigned photon_batch(const struct photon *p)
{
    return ((unsigned)p->flags & PHOTON_BATCH_BITS) >> PHOTON_BATCH_SHIFT;
}
