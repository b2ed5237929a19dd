/*
 * app/work_file.c -- writing and reading the file of a render's global work
 * (work_file.h).
 *
 * Numbers travel through base/binary.h, which makes the file's bytes the same on every
 * machine and checks every count against the bytes left before anything is allocated.
 * This file lays out the parts whose structs are public (the kd-trees' photons, the
 * cache's records); the illumination maps keep their layout to themselves and write and
 * read it in photon/illumination_map.c.
 */
#include "work_file.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/binary.h"
#include "../base/hash.h"
#include "../base/output.h"
#include "../photon/illumination_map.h"

#define PHOTON_BYTES 20   /* a photon in the file, as in memory (photon.h)   */
#define RECORD_DOUBLES 28 /* an irradiance record in the file: 28 doubles    */

extern char float_is_4_bytes[sizeof(float) == 4 ? 1 : -1];

/* ---- Ranges: what the writer refuses to save and the reader to load (work_file.h) ---- */

#define PHOTON_KINDS (PHOTON_DIRECT | PHOTON_CAUSTIC | PHOTON_INDIRECT | PHOTON_SHADOW)
#define UNIT_TOLERANCE 1e-9 /* |n| of a record's unit normal: normalised in double */

/* Photon i of map m within its ranges; name the file, for messages. */
static int check_photon(const struct photon *p, size_t m, size_t i, const char *name,
                        struct error *err)
{
    struct vec3 power = photon_power(p);
    if (!isfinite(p->pos[0]) || !isfinite(p->pos[1]) || !isfinite(p->pos[2]))
        return error_set(err, name, 0, "map %zu, photon %zu: its position is not finite", m,
                         i);
    unsigned kind = p->flags & PHOTON_KINDS; /* the other bits, side and batch, take any value */
    if (kind != PHOTON_DIRECT && kind != PHOTON_CAUSTIC && kind != PHOTON_INDIRECT &&
        kind != PHOTON_SHADOW)
        return error_set(err, name, 0, "map %zu, photon %zu: flags %u are not one photon kind",
                         m, i, (unsigned)p->flags);
    if (vec3_max_component(power) > WORK_PHOTON_POWER_MAX)
        return error_set(err, name, 0, "map %zu, photon %zu: power %g W is more than any "
                         "render's photon carries (%g W)", m, i, vec3_max_component(power),
                         WORK_PHOTON_POWER_MAX);
    return 0;
}

static int finite3(struct vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

/* Cache record i within its ranges (irradiance_cache_add()'s terms). */
static int check_record(const struct irradiance_record *rec, size_t i, const char *name,
                        struct error *err)
{
    int finite = finite3(rec->p) && finite3(rec->n) && finite3(rec->e) && isfinite(rec->r);
    for (int c = 0; c < 3; c++)
        finite = finite && finite3(rec->grad_r[c]) && finite3(rec->grad_t[c]);
    if (!finite)
        return error_set(err, name, 0, "cache record %zu: a number is not finite", i);
    if (!(rec->r > 0))
        return error_set(err, name, 0, "cache record %zu: radius %g is not positive", i,
                         rec->r);
    if (rec->e.x < 0 || rec->e.y < 0 || rec->e.z < 0)
        return error_set(err, name, 0, "cache record %zu: irradiance (%g, %g, %g) is "
                         "negative", i, rec->e.x, rec->e.y, rec->e.z);
    if (!(fabs(vec3_length(rec->n) - 1) <= UNIT_TOLERANCE))
        return error_set(err, name, 0, "cache record %zu: its normal is not of unit length "
                         "(%g)", i, vec3_length(rec->n));
    return 0;
}

/* Every photon and record of work within its ranges, before a byte is written. */
static int check_work(const struct global_work *work, const char *name, struct error *err)
{
    for (size_t m = 0; m < work->n_maps; m++)
        for (size_t i = 1; work->maps[m] != NULL && i <= work->maps[m]->n_photons; i++)
            if (check_photon(&work->maps[m]->photons[i], m, i, name, err) < 0)
                return -1;
    for (size_t i = 0; i < work->n_records; i++)
        if (check_record(&work->records[i], i, name, err) < 0)
            return -1;
    return 0;
}

/* err's message led by what was being done: the checks, the reader's and binary.h's
 * messages say what is wrong, this says that the file was being saved or loaded, and for
 * which option. Keeps err's kind (a failed write or bad input). */
static int say_doing(struct error *err, const char *doing)
{
    if (err != NULL) {
        int failed_write = err->failed_write;
        error_set(err, err->file, err->line, "%s: %s", doing, err->message);
        err->failed_write = failed_write;
    }
    return -1;
}

/* ---- Writing ----------------------------------------------------------------------- */

static void put_vec3(struct binary_writer *w, struct vec3 v)
{
    binary_put_double(w, v.x);
    binary_put_double(w, v.y);
    binary_put_double(w, v.z);
}

static void put_photon(struct binary_writer *w, const struct photon *p)
{
    unsigned char bytes[PHOTON_BYTES];
    for (int k = 0; k < 3; k++) {
        uint32_t bits;
        memcpy(&bits, &p->pos[k], sizeof bits);
        for (int i = 0; i < 4; i++)
            bytes[4 * k + i] = (unsigned char)(bits >> (8 * i));
    }
    memcpy(bytes + 12, p->power, 4);
    bytes[16] = p->theta;
    bytes[17] = p->phi;
    bytes[18] = p->plane;
    bytes[19] = p->flags;
    binary_put_bytes(w, bytes, sizeof bytes);
}

static void put_record(struct binary_writer *w, const struct irradiance_record *r)
{
    put_vec3(w, r->p);
    put_vec3(w, r->n);
    put_vec3(w, r->e);
    binary_put_double(w, r->r);
    for (int c = 0; c < 3; c++)
        put_vec3(w, r->grad_r[c]);
    for (int c = 0; c < 3; c++)
        put_vec3(w, r->grad_t[c]);
}

int work_file_write(const char *name, uint64_t hash, const struct global_work *work,
                    struct error *err)
{
    struct binary_writer w = {NULL, FNV1A_OFFSET_BASIS};
    if (check_work(work, name, err) < 0) {
        if (err != NULL)
            err->failed_write = 1; /* the render's own work: no input of the user's is bad */
        return say_doing(err, "cannot save the work (--save-photons)");
    }
    w.f = output_open(name, err);
    if (w.f == NULL)
        return -1;
    binary_put_bytes(&w, (const unsigned char *)WORK_FILE_MAGIC, 8);
    binary_put_uint(&w, WORK_FILE_VERSION, 4);
    binary_put_uint(&w, hash, 8);
    binary_put_uint(&w, work->n_maps, 4);
    for (size_t m = 0; m < work->n_maps; m++) {
        const struct kdtree *map = work->maps[m];
        binary_put_uint(&w, map != NULL, 1);
        if (map == NULL)
            continue;
        binary_put_uint(&w, map->n_photons, 8);
        for (size_t i = 1; i <= map->n_photons; i++)
            put_photon(&w, &map->photons[i]);
    }
    binary_put_uint(&w, work->n_records, 8);
    for (size_t i = 0; i < work->n_records; i++)
        put_record(&w, &work->records[i]);
    binary_put_uint(&w, work->illumination != NULL, 1);
    if (work->illumination != NULL)
        illumination_maps_write(work->illumination, &w);
    binary_put_checksum(&w);
    return output_commit(w.f, err);
}

/* ---- Reading ----------------------------------------------------------------------- */

/* The photon of bytes (put_photon's layout). */
static struct photon photon_of_bytes(const unsigned char *bytes)
{
    struct photon p;
    for (int k = 0; k < 3; k++) {
        uint32_t bits = 0;
        for (int i = 3; i >= 0; i--)
            bits = bits << 8 | bytes[4 * k + i];
        memcpy(&p.pos[k], &bits, sizeof bits);
    }
    memcpy(p.power, bytes + 12, 4);
    p.theta = bytes[16];
    p.phi = bytes[17];
    p.plane = bytes[18];
    p.flags = bytes[19];
    return p;
}

/* Map m of the file into *map (NULL when the file says it does not exist). */
static int get_map(struct binary_reader *r, size_t m, struct kdtree **map, struct error *err)
{
    int present;
    uint64_t n;
    char what[48];
    snprintf(what, sizeof what, "map %zu's header", m);
    if (binary_get_flag(r, what, &present, err) < 0)
        return -1;
    if (!present)
        return 0;
    if (binary_get_uint(r, 8, what, &n, err) < 0 ||
        binary_fits(r, n, PHOTON_BYTES, "photons", err) < 0)
        return -1;
    struct photon *heap = xmalloc((size_t)n + 1, sizeof *heap, "photon map");
    for (size_t i = 1; i <= n; i++) {
        unsigned char bytes[PHOTON_BYTES];
        if (binary_get_bytes(r, bytes, sizeof bytes, "a map's photons", err) < 0) {
            xfree(heap);
            return -1;
        }
        heap[i] = photon_of_bytes(bytes);
        if (check_photon(&heap[i], m, i, r->name, err) < 0) {
            xfree(heap);
            return -1;
        }
    }
    *map = kdtree_from_heap(heap, (size_t)n); /* takes heap */
    if (*map == NULL)
        return error_set(err, r->name, 0, "map %zu is not a balanced kd-tree", m);
    return 0;
}

/* Record i into *rec, within its ranges (check_record). */
static int get_record(struct binary_reader *r, size_t i, struct irradiance_record *rec,
                      struct error *err)
{
    double x[RECORD_DOUBLES];
    char what[40];
    snprintf(what, sizeof what, "cache record %zu", i);
    for (int k = 0; k < RECORD_DOUBLES; k++)
        if (binary_get_double(r, what, &x[k], err) < 0)
            return -1;
    rec->p = vec3(x[0], x[1], x[2]);
    rec->n = vec3(x[3], x[4], x[5]);
    rec->e = vec3(x[6], x[7], x[8]);
    rec->r = x[9];
    for (int c = 0; c < 3; c++) {
        rec->grad_r[c] = vec3(x[10 + 3 * c], x[11 + 3 * c], x[12 + 3 * c]);
        rec->grad_t[c] = vec3(x[19 + 3 * c], x[20 + 3 * c], x[21 + 3 * c]);
    }
    return check_record(rec, i, r->name, err);
}

/* Magic, version and hash: the file is work of this program's kind, for this render. */
static int get_header(struct binary_reader *r, uint64_t hash, struct error *err)
{
    unsigned char magic[8];
    uint64_t version, saved_hash;
    if (binary_get_bytes(r, magic, 8, "the magic", NULL) < 0 ||
        memcmp(magic, WORK_FILE_MAGIC, 8) != 0)
        return error_set(err, r->name, 0, "not a file of photon's saved global work "
                         "(--save-photons)");
    if (binary_get_uint(r, 4, "the header", &version, err) < 0)
        return -1;
    if (version != WORK_FILE_VERSION)
        return error_set(err, r->name, 0, "version %llu of the saved work; this photon reads "
                         "version %d (save the work again with this photon's "
                         "--save-photons)", (unsigned long long)version, WORK_FILE_VERSION);
    if (binary_get_uint(r, 8, "the header", &saved_hash, err) < 0)
        return -1;
    if (saved_hash != hash)
        return error_set(err, r->name, 0, "saved from other scene files, mode, seed or "
                         "options than this render's (hash %016llx, not %016llx)",
                         (unsigned long long)saved_hash, (unsigned long long)hash);
    return 0;
}

/* The cache's records into work. */
static int get_records(struct binary_reader *r, struct global_work *work, struct error *err)
{
    uint64_t n_records;
    if (binary_get_uint(r, 8, "the cache's header", &n_records, err) < 0 ||
        binary_fits(r, n_records, BINARY_DOUBLE_BYTES * RECORD_DOUBLES, "cache records",
                    err) < 0)
        return -1;
    if (n_records > 0)
        work->records = xmalloc((size_t)n_records, sizeof *work->records, "cache records");
    work->n_records = (size_t)n_records;
    for (size_t i = 0; i < work->n_records; i++)
        if (get_record(r, i, &work->records[i], err) < 0)
            return -1;
    return 0;
}

/* The illumination maps into work, when the file holds them. */
static int get_illumination(struct binary_reader *r, struct global_work *work,
                            struct error *err)
{
    int present;
    if (binary_get_flag(r, "the illumination maps' header", &present, err) < 0)
        return -1;
    if (!present)
        return 0;
    work->illumination = illumination_maps_read(r, err);
    return work->illumination != NULL ? 0 : -1;
}

static int get_work(struct binary_reader *r, uint64_t hash, struct global_work *work,
                    struct error *err)
{
    uint64_t n_maps;
    if (get_header(r, hash, err) < 0 || binary_get_uint(r, 4, "the header", &n_maps, err) < 0 ||
        binary_fits(r, n_maps, 1, "maps", err) < 0)
        return -1;
    if (n_maps == 0)
        return error_set(err, r->name, 0, "holds no photon map");
    global_work_add_maps(work, (size_t)n_maps);
    for (size_t m = 0; m < work->n_maps; m++)
        if (get_map(r, m, &work->maps[m], err) < 0)
            return -1;
    if (get_records(r, work, err) < 0 || get_illumination(r, work, err) < 0)
        return -1;
    return binary_get_checksum(r, err);
}

int work_file_read(const char *name, uint64_t hash, struct global_work *work,
                   struct error *err)
{
    struct binary_reader r;
    int status = binary_open(name, &r, err);
    if (status == 0) {
        status = get_work(&r, hash, work, err);
        fclose(r.f);
    }
    return status < 0 ? say_doing(err, "cannot load the saved work (--load-photons)") : 0;
}
