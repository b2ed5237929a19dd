/*
 * base/vec3.h -- three-component vectors in double precision.
 *
 * Used for points, directions and RGB alike; every operation is a small static inline
 * function, passed and returned by value. PI is defined here because M_PI is not C99.
 */
#ifndef PHOTON_VEC3_H
#define PHOTON_VEC3_H

#include <math.h>

#define PI 3.14159265358979323846 /* to double precision and beyond */

struct vec3 {
    double x, y, z;
};

static inline struct vec3 vec3(double x, double y, double z)
{
    struct vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static inline struct vec3 vec3_zero(void) { return vec3(0.0, 0.0, 0.0); }
static inline struct vec3 vec3_add(struct vec3 a, struct vec3 b)
{
    return vec3(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline struct vec3 vec3_sub(struct vec3 a, struct vec3 b)
{
    return vec3(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline struct vec3 vec3_mul(struct vec3 a, struct vec3 b)
{
    return vec3(a.x * b.x, a.y * b.y, a.z * b.z);
}
static inline struct vec3 vec3_scale(struct vec3 a, double s)
{
    return vec3(a.x * s, a.y * s, a.z * s);
}
static inline struct vec3 vec3_neg(struct vec3 a) { return vec3(-a.x, -a.y, -a.z); }
static inline double vec3_dot(struct vec3 a, struct vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline struct vec3 vec3_cross(struct vec3 a, struct vec3 b)
{
    return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double vec3_length2(struct vec3 a) { return vec3_dot(a, a); }
static inline double vec3_length(struct vec3 a) { return sqrt(vec3_dot(a, a)); }

/* a + b * s, the ray equation and its relatives. */
static inline struct vec3 vec3_madd(struct vec3 a, struct vec3 b, double s)
{
    return vec3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}

/* Unit vector along a; the zero vector stays zero rather than becoming NaN. */
static inline struct vec3 vec3_normalize(struct vec3 a)
{
    double len = vec3_length(a);
    if (!(len > 0))
        return vec3_zero();
    return vec3_scale(a, 1.0 / len);
}

static inline double vec3_max_component(struct vec3 a)
{
    return fmax(a.x, fmax(a.y, a.z));
}

/* max(|x|, |y|, |z|): the magnitude that scales ray offsets and tolerances. */
static inline double vec3_max_abs(struct vec3 a)
{
    return fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
}

static inline double vec3_get(struct vec3 a, int axis)
{
    return axis == 0 ? a.x : axis == 1 ? a.y : a.z;
}

static inline struct vec3 vec3_min(struct vec3 a, struct vec3 b)
{
    return vec3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
}
static inline struct vec3 vec3_max(struct vec3 a, struct vec3 b)
{
    return vec3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
}

static inline int vec3_is_finite(struct vec3 a)
{
    return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

/* Rec. 709 luminance of a linear RGB value: the scalar used for Russian roulette and power. */
static inline double vec3_luminance(struct vec3 a)
{
    return 0.2126 * a.x + 0.7152 * a.y + 0.0722 * a.z;
}

/* Two unit vectors t, b completing the unit normal n to a right-handed frame (t, b, n).
 * Branch-free form of Duff et al. 2017, "Building an orthonormal basis, revisited". */
static inline void vec3_frame(struct vec3 n, struct vec3 *t, struct vec3 *b)
{
    double sign = n.z >= 0 ? 1.0 : -1.0;
    double a = -1.0 / (sign + n.z);
    double c = n.x * n.y * a;
    *t = vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = vec3(c, sign + n.y * n.y * a, -n.y);
}

#endif
