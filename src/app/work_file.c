/*
 * app/work_file.c -- writing and reading the file of a render's global work
 * (work_file.h).
 *
 * Numbers go out one byte at a time, lowest first, and come back the same way, so the
 * file does not depend on the machine's byte order or on how a compiler lays out a
 * struct. Floats and doubles travel as their IEEE 754 bits (C99 does not promise IEEE
 * 754, but every machine photon runs on has it, and the sizes are checked below). The
 * reader knows the file's size before it allocates anything: a count that would need
 * more bytes than the file has left is reported as truncation, not tried.
 */
#include "work_file.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/hash.h"

#define PHOTON_BYTES 20  /* a photon in the file, as in memory (photon.h)   */
#define RECORD_DOUBLES 28 /* an irradiance record in the file: 28 doubles    */

extern char float_is_4_bytes[sizeof(float) == 4 ? 1 : -1];
extern char double_is_8_bytes[sizeof(double) == 8 ? 1 : -1];

/* ---- Writing ----------------------------------------------------------------------- */

struct work_writer {
    FILE *f;
    uint64_t checksum; /* FNV-1a of every byte written so far */
};

static void put_bytes(struct work_writer *w, const unsigned char *bytes, size_t n)
{
    fwrite(bytes, 1, n, w->f); /* a failed write shows in ferror(), checked at the commit */
    w->checksum = fnv1a(w->checksum, bytes, n);
}

/* The n_bytes lowest bytes of v, lowest first. */
static void put_uint(struct work_writer *w, uint64_t v, int n_bytes)
{
    unsigned char bytes[8];
    for (int i = 0; i < n_bytes; i++)
        bytes[i] = (unsigned char)(v >> (8 * i));
    put_bytes(w, bytes, (size_t)n_bytes);
}

static void put_double(struct work_writer *w, double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    put_uint(w, bits, 8);
}

static void put_vec3(struct work_writer *w, struct vec3 v)
{
    put_double(w, v.x);
    put_double(w, v.y);
    put_double(w, v.z);
}

static void put_photon(struct work_writer *w, const struct photon *p)
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
    put_bytes(w, bytes, sizeof bytes);
}

static void put_record(struct work_writer *w, const struct irradiance_record *r)
{
    put_vec3(w, r->p);
    put_vec3(w, r->n);
    put_vec3(w, r->e);
    put_double(w, r->r);
    for (int c = 0; c < 3; c++)
        put_vec3(w, r->grad_r[c]);
    for (int c = 0; c < 3; c++)
        put_vec3(w, r->grad_t[c]);
}

int work_file_write(const char *name, uint64_t hash, const struct global_work *work,
                    struct error *err)
{
    struct work_writer w = {NULL, FNV1A_OFFSET_BASIS};
    w.f = output_open(name, err);
    if (w.f == NULL)
        return -1;
    put_bytes(&w, (const unsigned char *)WORK_FILE_MAGIC, 8);
    put_uint(&w, WORK_FILE_VERSION, 4);
    put_uint(&w, hash, 8);
    put_uint(&w, work->n_maps, 4);
    for (size_t m = 0; m < work->n_maps; m++) {
        const struct kdtree *map = work->maps[m];
        put_uint(&w, map != NULL, 1);
        if (map == NULL)
            continue;
        put_uint(&w, map->n_photons, 8);
        for (size_t i = 1; i <= map->n_photons; i++)
            put_photon(&w, &map->photons[i]);
    }
    put_uint(&w, work->n_records, 8);
    for (size_t i = 0; i < work->n_records; i++)
        put_record(&w, &work->records[i]);
    put_uint(&w, w.checksum, 8); /* the checksum does not cover itself */
    return output_commit(w.f, err);
}

/* ---- Reading ----------------------------------------------------------------------- */

struct work_reader {
    FILE *f;
    const char *name;  /* for messages                                */
    long size;         /* of the whole file, in bytes                 */
    uint64_t checksum; /* FNV-1a of every byte read so far            */
};

/* n bytes, of the part of the file that what names (for the message). */
static int get_bytes(struct work_reader *r, unsigned char *bytes, size_t n, const char *what,
                     struct error *err)
{
    if (fread(bytes, 1, n, r->f) != n)
        return error_set(err, r->name, 0, "truncated: the file ends inside %s", what);
    r->checksum = fnv1a(r->checksum, bytes, n);
    return 0;
}

static int get_uint(struct work_reader *r, int n_bytes, const char *what, uint64_t *v,
                    struct error *err)
{
    unsigned char bytes[8];
    if (get_bytes(r, bytes, (size_t)n_bytes, what, err) < 0)
        return -1;
    *v = 0;
    for (int i = n_bytes - 1; i >= 0; i--)
        *v = *v << 8 | bytes[i];
    return 0;
}

/* Whether count items of item_bytes each fit in what is left of the file; the message
 * says truncation otherwise, before anything is allocated for them. */
static int fits_in_file(const struct work_reader *r, uint64_t count, size_t item_bytes,
                        const char *what, struct error *err)
{
    long at = ftell(r->f);
    uint64_t left = at >= 0 && at <= r->size ? (uint64_t)(r->size - at) : 0;
    if (count > left / item_bytes)
        return error_set(err, r->name, 0, "truncated: %llu %s need %llu bytes, %llu are "
                         "left", (unsigned long long)count, what,
                         (unsigned long long)count * item_bytes, (unsigned long long)left);
    return 0;
}

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
static int get_map(struct work_reader *r, size_t m, struct kdtree **map, struct error *err)
{
    uint64_t present, n;
    if (get_uint(r, 1, "a map's header", &present, err) < 0)
        return -1;
    if (present > 1)
        return error_set(err, r->name, 0, "map %zu: expected 0 or 1 before it, got %llu", m,
                         (unsigned long long)present);
    if (present == 0)
        return 0;
    if (get_uint(r, 8, "a map's header", &n, err) < 0 ||
        fits_in_file(r, n, PHOTON_BYTES, "photons", err) < 0)
        return -1;
    struct photon *heap = xmalloc((size_t)n + 1, sizeof *heap, "photon map");
    for (size_t i = 1; i <= n; i++) {
        unsigned char bytes[PHOTON_BYTES];
        if (get_bytes(r, bytes, sizeof bytes, "a map's photons", err) < 0) {
            free(heap);
            return -1;
        }
        heap[i] = photon_of_bytes(bytes);
    }
    *map = kdtree_from_heap(heap, (size_t)n); /* takes heap */
    if (*map == NULL)
        return error_set(err, r->name, 0, "map %zu is not a balanced kd-tree", m);
    return 0;
}

static int get_double(struct work_reader *r, double *x, struct error *err)
{
    uint64_t bits;
    if (get_uint(r, 8, "the cache's records", &bits, err) < 0)
        return -1;
    memcpy(x, &bits, sizeof *x);
    return 0;
}

/* Record i into *rec: 28 doubles, all finite, R > 0 (irradiance_cache_add()'s terms). */
static int get_record(struct work_reader *r, size_t i, struct irradiance_record *rec,
                      struct error *err)
{
    double x[RECORD_DOUBLES];
    for (int k = 0; k < RECORD_DOUBLES; k++)
        if (get_double(r, &x[k], err) < 0)
            return -1;
    for (int k = 0; k < RECORD_DOUBLES; k++)
        if (!isfinite(x[k]))
            return error_set(err, r->name, 0, "cache record %zu: number %d is not finite",
                             i, k + 1);
    if (!(x[9] > 0))
        return error_set(err, r->name, 0, "cache record %zu: radius %g is not positive", i,
                         x[9]);
    rec->p = vec3(x[0], x[1], x[2]);
    rec->n = vec3(x[3], x[4], x[5]);
    rec->e = vec3(x[6], x[7], x[8]);
    rec->r = x[9];
    for (int c = 0; c < 3; c++) {
        rec->grad_r[c] = vec3(x[10 + 3 * c], x[11 + 3 * c], x[12 + 3 * c]);
        rec->grad_t[c] = vec3(x[19 + 3 * c], x[20 + 3 * c], x[21 + 3 * c]);
    }
    return 0;
}

/* Magic, version and hash: the file is work of this program's kind, for this render. */
static int get_header(struct work_reader *r, uint64_t hash, struct error *err)
{
    unsigned char magic[8];
    uint64_t version, saved_hash;
    if (fread(magic, 1, 8, r->f) != 8 || memcmp(magic, WORK_FILE_MAGIC, 8) != 0)
        return error_set(err, r->name, 0, "not a file of photon's saved global work "
                         "(--save-photons)");
    r->checksum = fnv1a(r->checksum, magic, 8);
    if (get_uint(r, 4, "the header", &version, err) < 0)
        return -1;
    if (version != WORK_FILE_VERSION)
        return error_set(err, r->name, 0, "version %llu of the saved work; this photon reads "
                         "version %d", (unsigned long long)version, WORK_FILE_VERSION);
    if (get_uint(r, 8, "the header", &saved_hash, err) < 0)
        return -1;
    if (saved_hash != hash)
        return error_set(err, r->name, 0, "saved from other scene files, mode, seed or "
                         "options than this render's (hash %016llx, not %016llx)",
                         (unsigned long long)saved_hash, (unsigned long long)hash);
    return 0;
}

static int get_work(struct work_reader *r, uint64_t hash, struct global_work *work,
                    struct error *err)
{
    uint64_t n_maps, n_records, checksum;
    if (get_header(r, hash, err) < 0 || get_uint(r, 4, "the header", &n_maps, err) < 0 ||
        fits_in_file(r, n_maps, 1, "maps", err) < 0)
        return -1;
    if (n_maps == 0)
        return error_set(err, r->name, 0, "holds no photon map");
    global_work_add_maps(work, (size_t)n_maps);
    for (size_t m = 0; m < work->n_maps; m++)
        if (get_map(r, m, &work->maps[m], err) < 0)
            return -1;
    if (get_uint(r, 8, "the cache's header", &n_records, err) < 0 ||
        fits_in_file(r, n_records, 8 * RECORD_DOUBLES, "cache records", err) < 0)
        return -1;
    if (n_records > 0)
        work->records = xmalloc((size_t)n_records, sizeof *work->records, "cache records");
    work->n_records = (size_t)n_records;
    for (size_t i = 0; i < work->n_records; i++)
        if (get_record(r, i, &work->records[i], err) < 0)
            return -1;
    uint64_t sum = r->checksum;
    if (get_uint(r, 8, "the checksum", &checksum, err) < 0)
        return -1;
    if (checksum != sum)
        return error_set(err, r->name, 0, "damaged: its checksum is %016llx, its bytes sum "
                         "to %016llx", (unsigned long long)checksum, (unsigned long long)sum);
    if (getc(r->f) != EOF)
        return error_set(err, r->name, 0, "unexpected bytes after the checksum");
    return 0;
}

int work_file_read(const char *name, uint64_t hash, struct global_work *work,
                   struct error *err)
{
    struct work_reader r = {NULL, name, 0, FNV1A_OFFSET_BASIS};
    r.f = fopen(name, "rb");
    if (r.f == NULL)
        return error_set(err, name, 0, "cannot open: %s", strerror(errno));
    if (fseek(r.f, 0, SEEK_END) != 0 || (r.size = ftell(r.f)) < 0 ||
        fseek(r.f, 0, SEEK_SET) != 0) {
        fclose(r.f);
        return error_set(err, name, 0, "cannot tell its size (is it a regular file?)");
    }
    int status = get_work(&r, hash, work, err);
    fclose(r.f);
    return status;
}
