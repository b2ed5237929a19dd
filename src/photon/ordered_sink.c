/*
 * photon/ordered_sink.c -- photons handed on in the order of where they lie
 * (ordered_sink.h).
 */
#include "ordered_sink.h"

#include <string.h>

#include "../base/alloc.h"

#define ORDERED_CELLS ((size_t)ORDERED_GRID * ORDERED_GRID * ORDERED_GRID)

void ordered_sink_create(struct ordered_sink *os, struct aabb box, struct photon_sink to)
{
    memset(os, 0, sizeof *os);
    os->to = to;
    os->box = box;
    os->cell_start = xmalloc(ORDERED_CELLS + 1, sizeof *os->cell_start, "photon order");
}

/* Coordinate x's cell along an axis from lo to hi: 0 .. ORDERED_GRID - 1. */
static unsigned cell_along(double x, double lo, double hi)
{
    double t = hi > lo ? (x - lo) / (hi - lo) * ORDERED_GRID : 0.0;
    if (!(t > 0.0))
        return 0;
    return t >= ORDERED_GRID - 1 ? ORDERED_GRID - 1 : (unsigned)t;
}

/* The bits of c, spaced three apart: bit b of c becomes bit 3 b. */
static unsigned spaced(unsigned c)
{
    unsigned s = 0;
    for (unsigned b = 0; (1u << b) < ORDERED_GRID; b++)
        s |= ((c >> b) & 1u) << (3 * b);
    return s;
}

/* The Z-order index of the cell holding p. */
static unsigned z_order_cell(const struct aabb *box, struct vec3 p)
{
    return spaced(cell_along(p.x, box->lo.x, box->hi.x)) |
           spaced(cell_along(p.y, box->lo.y, box->hi.y)) << 1 |
           spaced(cell_along(p.z, box->lo.z, box->hi.z)) << 2;
}

int ordered_sink_flush(struct ordered_sink *os)
{
    size_t *start = os->cell_start;
    memset(start, 0, (ORDERED_CELLS + 1) * sizeof *start);
    for (size_t i = 0; i < os->n; i++) /* a counting sort: the counts, ... */
        start[os->cell[i] + 1]++;
    for (size_t c = 0; c < ORDERED_CELLS; c++) /* ... where each cell starts, ... */
        start[c + 1] += start[c];
    for (size_t i = 0; i < os->n; i++) /* ... and each photon after its cell's earlier ones */
        os->order[start[os->cell[i]]++] = i;
    size_t n = os->n;
    os->n = 0;
    for (size_t k = 0; k < n; k++)
        if (os->to.store(os->to.context, &os->held[os->order[k]]) < 0)
            return -1;
    return 0;
}

static int hold(void *context, const struct photon_event *photon)
{
    struct ordered_sink *os = context;
    if (os->n == ORDERED_CHUNK && ordered_sink_flush(os) < 0)
        return -1;
    if (os->n == os->capacity) {
        size_t room = os->capacity > 0 ? 2 * os->capacity : 4096;
        os->capacity = room < ORDERED_CHUNK ? room : ORDERED_CHUNK;
        os->held = xrealloc(os->held, os->capacity, sizeof *os->held, "photon order");
        os->cell = xrealloc(os->cell, os->capacity, sizeof *os->cell, "photon order");
        os->order = xrealloc(os->order, os->capacity, sizeof *os->order, "photon order");
    }
    os->held[os->n] = *photon;
    os->cell[os->n] = z_order_cell(&os->box, photon->position);
    os->n++;
    return 0;
}

struct photon_sink ordered_sink_of(struct ordered_sink *os)
{
    struct photon_sink sink;
    sink.store = hold;
    sink.context = os;
    return sink;
}

void ordered_sink_free(struct ordered_sink *os)
{
    xfree(os->held);
    xfree(os->cell);
    xfree(os->order);
    xfree(os->cell_start);
    memset(os, 0, sizeof *os);
}
