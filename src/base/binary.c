/*
 * base/binary.c -- numbers in a binary file, the same bytes on every machine (binary.h).
 */
#include "binary.h"

#include <math.h>
#include <string.h>

#include "hash.h"
#include "input.h"

extern char double_is_8_bytes[sizeof(double) == BINARY_DOUBLE_BYTES ? 1 : -1];

/* ---- Writing ----------------------------------------------------------------------- */

void binary_put_bytes(struct binary_writer *w, const unsigned char *bytes, size_t n)
{
    fwrite(bytes, 1, n, w->f); /* a failed write shows in ferror(), checked at the commit */
    w->checksum = fnv1a(w->checksum, bytes, n);
}

void binary_put_uint(struct binary_writer *w, uint64_t v, int n_bytes)
{
    unsigned char bytes[8];
    for (int i = 0; i < n_bytes; i++)
        bytes[i] = (unsigned char)(v >> (8 * i));
    binary_put_bytes(w, bytes, (size_t)n_bytes);
}

void binary_put_double(struct binary_writer *w, double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    binary_put_uint(w, bits, 8);
}

void binary_put_checksum(struct binary_writer *w)
{
    binary_put_uint(w, w->checksum, 8); /* the checksum does not cover itself */
}

/* ---- Reading ----------------------------------------------------------------------- */

int binary_open(const char *name, struct binary_reader *r, struct error *err)
{
    struct input in;
    r->name = name;
    r->checksum = FNV1A_OFFSET_BASIS;
    if (input_open(&in, name, err) < 0)
        return -1;
    r->f = in.f; /* the caller closes it */
    r->size = in.size;
    return 0;
}

int binary_get_bytes(struct binary_reader *r, unsigned char *bytes, size_t n, const char *what,
                     struct error *err)
{
    if (fread(bytes, 1, n, r->f) != n)
        return error_set(err, r->name, 0, "truncated: the file ends inside %s", what);
    r->checksum = fnv1a(r->checksum, bytes, n);
    return 0;
}

int binary_get_uint(struct binary_reader *r, int n_bytes, const char *what, uint64_t *v,
                    struct error *err)
{
    unsigned char bytes[8];
    if (binary_get_bytes(r, bytes, (size_t)n_bytes, what, err) < 0)
        return -1;
    *v = 0;
    for (int i = n_bytes - 1; i >= 0; i--)
        *v = *v << 8 | bytes[i];
    return 0;
}

int binary_get_flag(struct binary_reader *r, const char *what, int *flag, struct error *err)
{
    uint64_t v;
    if (binary_get_uint(r, 1, what, &v, err) < 0)
        return -1;
    if (v > 1)
        return error_set(err, r->name, 0, "%s: expected 0 or 1, got %llu", what,
                         (unsigned long long)v);
    *flag = (int)v;
    return 0;
}

int binary_get_double(struct binary_reader *r, const char *what, double *x,
                      struct error *err)
{
    uint64_t bits;
    if (binary_get_uint(r, 8, what, &bits, err) < 0)
        return -1;
    memcpy(x, &bits, sizeof *x);
    if (!isfinite(*x))
        return error_set(err, r->name, 0, "%s: a number is not finite", what);
    return 0;
}

int binary_fits(const struct binary_reader *r, uint64_t count, size_t item_bytes,
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

int binary_get_checksum(struct binary_reader *r, struct error *err)
{
    uint64_t sum = r->checksum, checksum;
    if (binary_get_uint(r, 8, "the checksum", &checksum, err) < 0)
        return -1;
    if (checksum != sum)
        return error_set(err, r->name, 0, "damaged: its checksum is %016llx, its bytes sum "
                         "to %016llx", (unsigned long long)checksum, (unsigned long long)sum);
    if (getc(r->f) != EOF)
        return error_set(err, r->name, 0, "unexpected bytes after the checksum");
    return 0;
}
