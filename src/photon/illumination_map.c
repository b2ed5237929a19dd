/*
 * photon/illumination_map.c -- two-level illumination maps (illumination_map.h).
 *
 * Layout: one struct di_map per covered primitive, found through an array indexed by
 * primitive id (NULL for primitives without parameters). A DI map is res_u x res_v
 * elements in row-major order (v the row); element (i, j) spans u in [i, i + 1] / res_u
 * and v in [j, j + 1] / res_v. Its CI sub-map, when there is one, splits that span into
 * ci_side x ci_side elements the same way. Values are 3
 * doubles per element: energy while photons arrive, irradiance after finishing.
 */
#include "illumination_map.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>

#include "../base/alloc.h"
#include "../base/binary.h"

struct di_map {
    int res_u, res_v; /* elements along u and v, 1..ILLUMINATION_MAX_SIDE        */
    int ci_side;      /* a CI sub-map's elements along u and v, 1..ILLUMINATION_CI_MAX_SIDE */
    double *di;       /* owned: 3 res_u res_v values                            */
    double **ci;      /* owned: res_u res_v sub-maps, each NULL or owned, 3
                         ci_side^2 values                                       */
};

struct illumination_maps {
    struct di_map **maps; /* owned: n_prims entries, NULL where not covered       */
    size_t n_prims;
    int finished;
};

static size_t di_elements(const struct di_map *d)
{
    return (size_t)d->res_u * (size_t)d->res_v;
}

static size_t ci_elements(const struct di_map *d)
{
    return (size_t)d->ci_side * (size_t)d->ci_side;
}

/* A DI map of the given sides, every element 0 and without a CI sub-map. */
static struct di_map *di_map_alloc(int res_u, int res_v, int ci_side)
{
    struct di_map *d = xmalloc(1, sizeof *d, "illumination map");
    d->res_u = res_u;
    d->res_v = res_v;
    d->ci_side = ci_side;
    d->di = xcalloc(3 * di_elements(d), sizeof *d->di, "illumination map");
    d->ci = xcalloc(di_elements(d), sizeof *d->ci, "illumination map");
    return d;
}

/* A CI sub-map for d, every element 0. */
static double *ci_map_alloc(const struct di_map *d)
{
    return xcalloc(3 * ci_elements(d), sizeof *d->di, "caustic illumination map");
}

/* Maps for n_prims primitives, none covered yet. */
static struct illumination_maps *maps_alloc(size_t n_prims, int finished)
{
    struct illumination_maps *maps = xmalloc(1, sizeof *maps, "illumination maps");
    maps->n_prims = n_prims;
    maps->maps = xcalloc(n_prims > 0 ? n_prims : 1, sizeof *maps->maps, "illumination maps");
    maps->finished = finished;
    return maps;
}

/* Elements along one parameter for an extent of length over elements of side h. */
static int elements_along(double length, double h)
{
    double n = ceil(length / h);
    return n < 1 ? 1 : n > ILLUMINATION_MAX_SIDE ? ILLUMINATION_MAX_SIDE : (int)n;
}

/* The DI map of prim, elements about h across along its parameter lines, CI elements
 * about footprint across (0: as DI's), or NULL when prim has no parameters. */
static struct di_map *di_map_create(const struct geometry *g, int prim, double h,
                                    double footprint)
{
    double length_u, length_v;
    if (!geometry_uv_extent(g, prim, &length_u, &length_v))
        return NULL;
    double side = footprint > 0 ? ceil(h / footprint) : 1;
    return di_map_alloc(elements_along(length_u, h), elements_along(length_v, h),
                        side > ILLUMINATION_CI_MAX_SIDE ? ILLUMINATION_CI_MAX_SIDE : (int)side);
}

struct illumination_maps *illumination_maps_create(const struct geometry *g, double diagonal,
                                                   const double *footprint,
                                                   const unsigned char *receives)
{
    assert(diagonal > 0 && isfinite(diagonal));
    struct illumination_maps *maps = maps_alloc(geometry_primitive_count(g), 0);
    double h = diagonal / ILLUMINATION_DI_PER_DIAGONAL;
    for (size_t i = 0; i < maps->n_prims; i++)
        if (receives == NULL || receives[i])
            maps->maps[i] = di_map_create(g, (int)i, h, footprint != NULL ? footprint[i] : 0);
    return maps;
}

void illumination_maps_free(struct illumination_maps *maps)
{
    if (maps == NULL)
        return;
    for (size_t i = 0; i < maps->n_prims; i++) {
        struct di_map *d = maps->maps[i];
        if (d == NULL)
            continue;
        for (size_t e = 0; e < di_elements(d); e++)
            xfree(d->ci[e]);
        xfree(d->ci);
        xfree(d->di);
        xfree(d);
    }
    xfree(maps->maps);
    xfree(maps);
}

int illumination_covers(const struct illumination_maps *maps, int prim)
{
    return prim >= 0 && (size_t)prim < maps->n_prims && maps->maps[prim] != NULL;
}

/* The index of the cell holding t in [0, 1] among n equal cells (t = 1 in the last). */
static int cell_of(double t, int n)
{
    int i = (int)floor(t * n);
    return i < 0 ? 0 : i >= n ? n - 1 : i;
}

/* Where (u, v) falls: its DI element and, within it, its CI element. */
static void locate(const struct di_map *d, double u, double v, size_t *di, size_t *ci)
{
    int i = cell_of(u, d->res_u), j = cell_of(v, d->res_v);
    *di = (size_t)j * (size_t)d->res_u + (size_t)i;
    int ci_i = cell_of(u * d->res_u - i, d->ci_side);
    int ci_j = cell_of(v * d->res_v - j, d->ci_side);
    *ci = (size_t)ci_j * (size_t)d->ci_side + (size_t)ci_i;
}

static void add_energy(double *value, struct vec3 energy)
{
    value[0] += energy.x;
    value[1] += energy.y;
    value[2] += energy.z;
}

void illumination_deposit(struct illumination_maps *maps, int prim, double u, double v,
                          struct vec3 energy, int caustic)
{
    assert(illumination_covers(maps, prim) && !maps->finished);
    struct di_map *d = maps->maps[prim];
    size_t di, ci;
    locate(d, u, v, &di, &ci);
    if (!caustic) {
        add_energy(&d->di[3 * di], energy);
        return;
    }
    if (d->ci[di] == NULL) /* the first caustic photon in this element: its CI sub-map */
        d->ci[di] = ci_map_alloc(d);
    add_energy(&d->ci[di][3 * ci], energy);
}

/* Divides the 3 values at value by area (none when the area is 0). */
static void to_irradiance(double *value, double area)
{
    for (int c = 0; c < 3; c++)
        value[c] = area > 0 ? value[c] / area : 0.0;
}

/* Every element of d, the primitive prim's, from energy to irradiance. */
static void finish_map(struct di_map *d, const struct geometry *g, int prim)
{
    double du = 1.0 / d->res_u, dv = 1.0 / d->res_v;
    double cu = du / d->ci_side, cv = dv / d->ci_side;
    for (int j = 0; j < d->res_v; j++) {
        for (int i = 0; i < d->res_u; i++) {
            size_t e = (size_t)j * (size_t)d->res_u + (size_t)i;
            to_irradiance(&d->di[3 * e],
                          geometry_uv_area(g, prim, i * du, (i + 1) * du, j * dv, (j + 1) * dv));
            for (int k = 0; d->ci[e] != NULL && k < d->ci_side * d->ci_side; k++) {
                double u0 = i * du + (k % d->ci_side) * cu;
                double v0 = j * dv + (k / d->ci_side) * cv;
                to_irradiance(&d->ci[e][3 * k], geometry_uv_area(g, prim, u0, u0 + cu, v0,
                                                                  v0 + cv));
            }
        }
    }
}

void illumination_maps_finish(struct illumination_maps *maps, const struct geometry *g)
{
    assert(!maps->finished);
    for (size_t i = 0; i < maps->n_prims; i++)
        if (maps->maps[i] != NULL)
            finish_map(maps->maps[i], g, (int)i);
    maps->finished = 1;
}

struct vec3 illumination_irradiance(const struct illumination_maps *maps, int prim, double u,
                                    double v, int caustic_only)
{
    assert(illumination_covers(maps, prim) && maps->finished);
    const struct di_map *d = maps->maps[prim];
    size_t di, ci;
    locate(d, u, v, &di, &ci);
    struct vec3 e = vec3_zero();
    if (d->ci[di] != NULL)
        e = vec3(d->ci[di][3 * ci], d->ci[di][3 * ci + 1], d->ci[di][3 * ci + 2]);
    if (!caustic_only)
        e = vec3_add(e, vec3(d->di[3 * di], d->di[3 * di + 1], d->di[3 * di + 2]));
    return e;
}

struct illumination_stats illumination_maps_stats(const struct illumination_maps *maps)
{
    struct illumination_stats st = {0, 0, 0, sizeof *maps};
    st.bytes += maps->n_prims * sizeof *maps->maps;
    for (size_t i = 0; i < maps->n_prims; i++) {
        const struct di_map *d = maps->maps[i];
        if (d == NULL)
            continue;
        size_t n = di_elements(d);
        st.n_maps++;
        st.di_elements += n;
        st.bytes += sizeof *d + n * (3 * sizeof *d->di + sizeof *d->ci);
        for (size_t e = 0; e < n; e++)
            if (d->ci[e] != NULL) {
                st.ci_maps++;
                st.bytes += 3 * ci_elements(d) * sizeof *d->ci[e];
            }
    }
    return st;
}

/* ---- Saving and loading (the layout illumination_map.h draws) ---------------------- */

static void put_irradiances(struct binary_writer *w, const double *values, size_t n)
{
    for (size_t i = 0; i < n; i++)
        binary_put_double(w, values[i]);
}

static void write_map(const struct di_map *d, struct binary_writer *w)
{
    binary_put_uint(w, (uint64_t)d->res_u, 2);
    binary_put_uint(w, (uint64_t)d->res_v, 2);
    binary_put_uint(w, (uint64_t)d->ci_side, 1);
    put_irradiances(w, d->di, 3 * di_elements(d));
    for (size_t e = 0; e < di_elements(d); e++) {
        binary_put_uint(w, d->ci[e] != NULL, 1);
        if (d->ci[e] != NULL)
            put_irradiances(w, d->ci[e], 3 * ci_elements(d));
    }
}

void illumination_maps_write(const struct illumination_maps *maps, struct binary_writer *w)
{
    assert(maps->finished);
    binary_put_uint(w, maps->n_prims, 4);
    for (size_t i = 0; i < maps->n_prims; i++) {
        binary_put_uint(w, maps->maps[i] != NULL, 1);
        if (maps->maps[i] != NULL)
            write_map(maps->maps[i], w);
    }
}

/* n irradiances into values (the caller has checked that the file holds their bytes);
 * what names the map for messages. Each is finite and not negative: an element's energy
 * is a sum of photons' powers over its area (illumination_maps_finish). */
static int get_irradiances(struct binary_reader *r, const char *what, double *values,
                           size_t n, struct error *err)
{
    for (size_t i = 0; i < n; i++) {
        if (binary_get_double(r, what, &values[i], err) < 0)
            return -1;
        if (values[i] < 0)
            return error_set(err, r->name, 0, "%s: irradiance %g is negative", what,
                             values[i]);
    }
    return 0;
}

/* One of a map's sides, of n_bytes, from 1 to max elements. */
static int get_side(struct binary_reader *r, const char *what, int n_bytes, int max, int *side,
                    struct error *err)
{
    uint64_t v;
    if (binary_get_uint(r, n_bytes, what, &v, err) < 0)
        return -1;
    if (v < 1 || v > (uint64_t)max)
        return error_set(err, r->name, 0, "%s: %llu elements along a side, not 1 to %d", what,
                         (unsigned long long)v, max);
    *side = (int)v;
    return 0;
}

/* Each DI element's flag and, where it is 1, its CI sub-map, into d. */
static int read_ci_maps(struct binary_reader *r, const char *what, struct di_map *d,
                        struct error *err)
{
    for (size_t e = 0; e < di_elements(d); e++) {
        int has_ci;
        if (binary_get_flag(r, what, &has_ci, err) < 0)
            return -1;
        if (!has_ci)
            continue;
        if (binary_fits(r, 3 * ci_elements(d), BINARY_DOUBLE_BYTES, "CI irradiances",
                        err) < 0)
            return -1;
        d->ci[e] = ci_map_alloc(d);
        if (get_irradiances(r, what, d->ci[e], 3 * ci_elements(d), err) < 0)
            return -1;
    }
    return 0;
}

/* Primitive prim's entry into maps->maps[prim], which owns what is read even when the
 * file fails part way. */
static int read_map(struct binary_reader *r, size_t prim, struct illumination_maps *maps,
                    struct error *err)
{
    char what[64];
    snprintf(what, sizeof what, "the illumination map of primitive %zu", prim);
    int present, res_u, res_v, ci_side;
    if (binary_get_flag(r, what, &present, err) < 0)
        return -1;
    if (!present)
        return 0;
    if (get_side(r, what, 2, ILLUMINATION_MAX_SIDE, &res_u, err) < 0 ||
        get_side(r, what, 2, ILLUMINATION_MAX_SIDE, &res_v, err) < 0 ||
        get_side(r, what, 1, ILLUMINATION_CI_MAX_SIDE, &ci_side, err) < 0 ||
        binary_fits(r, 3 * (uint64_t)res_u * (uint64_t)res_v, BINARY_DOUBLE_BYTES,
                    "DI irradiances", err) < 0)
        return -1;
    struct di_map *d = di_map_alloc(res_u, res_v, ci_side);
    maps->maps[prim] = d;
    if (get_irradiances(r, what, d->di, 3 * di_elements(d), err) < 0)
        return -1;
    return read_ci_maps(r, what, d, err);
}

struct illumination_maps *illumination_maps_read(struct binary_reader *r, struct error *err)
{
    uint64_t n_prims;
    if (binary_get_uint(r, 4, "the illumination maps' header", &n_prims, err) < 0 ||
        binary_fits(r, n_prims, 1, "illumination maps", err) < 0)
        return NULL;
    struct illumination_maps *maps = maps_alloc((size_t)n_prims, 1);
    for (size_t i = 0; i < maps->n_prims; i++)
        if (read_map(r, i, maps, err) < 0) {
            illumination_maps_free(maps);
            return NULL;
        }
    return maps;
}
