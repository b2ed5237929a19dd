/*
 * geom/mesh.c -- triangles over shared points, found by hashing (see mesh.h).
 *
 * The table maps a point's 24 bytes, hashed by FNV-1a (base/hash.h), to its index: slot
 * h mod table_size first, then the next slots in turn until the point or an empty slot.
 * It doubles before it would be more than half full, so a probe ends after about two
 * slots. Distinct bit patterns stay distinct points (+0 and -0, say), so every triangle
 * keeps exactly the coordinates it was given.
 */
#include "mesh.h"

#include <string.h>

#include "../base/alloc.h"
#include "../base/hash.h"

#define TABLE_MIN 64   /* slots of the first table; a power of 2 */

void mesh_init(struct mesh *m)
{
    m->points = NULL;
    m->n_points = m->cap_points = 0;
    m->triangles = NULL;
    m->n_triangles = m->cap_triangles = 0;
    m->table = NULL;
    m->table_size = 0;
}

void mesh_free(struct mesh *m)
{
    xfree(m->points);
    xfree(m->triangles);
    xfree(m->table);
    mesh_init(m);
}

static size_t slot_of(const double point[3], size_t table_size)
{
    return (size_t)(fnv1a(FNV1A_OFFSET_BASIS, point, 3 * sizeof point[0]) & (table_size - 1));
}

/* Makes the table table_size slots big and enters every point (invariant (2)). */
static void rebuild_table(struct mesh *m, size_t table_size)
{
    xfree(m->table);
    m->table = xcalloc(table_size, sizeof *m->table, "mesh point table");
    m->table_size = table_size;
    for (size_t i = 0; i < m->n_points; i++) {
        size_t s = slot_of(m->points[i], table_size);
        while (m->table[s] != 0)
            s = (s + 1) & (table_size - 1);
        m->table[s] = (uint32_t)i + 1;
    }
}

/* The index of the point p, appended if it is new. */
static uint32_t point_index(struct mesh *m, struct vec3 p)
{
    double point[3] = {p.x, p.y, p.z};
    if (m->table == NULL || 2 * (m->n_points + 1) > m->table_size) {
        size_t size = m->table_size < TABLE_MIN ? TABLE_MIN : m->table_size;
        while (2 * (m->n_points + 1) > size)
            size *= 2;
        rebuild_table(m, size);
    }
    size_t s = slot_of(point, m->table_size);
    for (; m->table[s] != 0; s = (s + 1) & (m->table_size - 1))
        if (memcmp(m->points[m->table[s] - 1], point, sizeof point) == 0)
            return m->table[s] - 1;
    if (m->n_points == m->cap_points) {
        m->cap_points = m->cap_points < 16 ? 16 : 2 * m->cap_points;
        m->points = xrealloc(m->points, m->cap_points, sizeof *m->points, "mesh points");
    }
    memcpy(m->points[m->n_points], point, sizeof point);
    m->table[s] = (uint32_t)m->n_points + 1;
    return (uint32_t)m->n_points++;
}

size_t mesh_add(struct mesh *m, const struct vec3 v[3], int normals, int material, int id)
{
    struct mesh_triangle tri;
    for (int i = 0; i < 3; i++)
        tri.corner[i] = point_index(m, v[i]);
    tri.normals = normals;
    tri.material = material;
    tri.id = id;
    if (m->n_triangles == m->cap_triangles) {
        m->cap_triangles = m->cap_triangles < 16 ? 16 : 2 * m->cap_triangles;
        m->triangles = xrealloc(m->triangles, m->cap_triangles, sizeof *m->triangles,
                                "triangles");
    }
    m->triangles[m->n_triangles] = tri;
    return m->n_triangles++;
}

/* The triangle's corners as triangle.h's corner pointers. */
static void corners_of(const struct mesh *m, const struct mesh_triangle *tri,
                       const double *corner[3])
{
    for (int i = 0; i < 3; i++)
        corner[i] = m->points[tri->corner[i]];
}

void mesh_corners(const struct mesh *m, const struct mesh_triangle *tri, struct vec3 v[3])
{
    for (int i = 0; i < 3; i++) {
        const double *p = m->points[tri->corner[i]];
        v[i] = vec3(p[0], p[1], p[2]);
    }
}

int mesh_is_degenerate(const struct mesh *m, const struct mesh_triangle *tri)
{
    const double *corner[3];
    corners_of(m, tri, corner);
    return corners_are_degenerate(corner);
}

struct aabb mesh_bounds(const struct mesh *m, const struct mesh_triangle *tri)
{
    const double *corner[3];
    corners_of(m, tri, corner);
    return corners_bounds(corner);
}

void mesh_shade(const struct mesh *m, const struct mesh_triangle *tri,
                const struct vec3 *normals, struct hit *hit)
{
    const double *corner[3];
    corners_of(m, tri, corner);
    corners_shade(corner, tri->material, normals, hit);
}

void mesh_finish(struct mesh *m)
{
    xfree(m->table);
    m->table = NULL;
    m->table_size = 0;
    if (m->n_triangles == 0)
        return;
    uint32_t *renamed = xmalloc(m->n_points, sizeof *renamed, "mesh point order");
    for (size_t i = 0; i < m->n_points; i++)
        renamed[i] = UINT32_MAX;   /* not used yet */
    double (*points)[3] = xmalloc(m->n_points, sizeof *points, "mesh points");
    size_t next = 0;
    for (size_t t = 0; t < m->n_triangles; t++) {
        for (int i = 0; i < 3; i++) {
            uint32_t old = m->triangles[t].corner[i];
            if (renamed[old] == UINT32_MAX) {
                memcpy(points[next], m->points[old], sizeof points[next]);
                renamed[old] = (uint32_t)next++;
            }
            m->triangles[t].corner[i] = renamed[old];
        }
    }
    xfree(renamed);
    xfree(m->points);
    m->points = points;   /* every point is some triangle's corner: next == n_points */
    m->cap_points = m->n_points;
    m->triangles = xrealloc(m->triangles, m->n_triangles, sizeof *m->triangles, "triangles");
    m->cap_triangles = m->n_triangles;
}

size_t mesh_bytes(const struct mesh *m)
{
    return m->cap_points * sizeof *m->points + m->cap_triangles * sizeof *m->triangles
           + m->table_size * sizeof *m->table;
}
