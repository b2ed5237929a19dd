/*
 * base/deflate.c -- deflate (RFC 1951) inside RFC 1950's zlib wrapper: the compressor that
 * base/inflate.c undoes, kept short rather than strong.
 *
 * Two stages, as RFC 1951 section 4 suggests them:
 *   - LZ77 (find_match): at each position, the longest earlier copy of the bytes ahead, at
 *     most 258 long and 32768 back, among the last MAX_CHAIN earlier positions whose next
 *     three bytes hash alike (one chain per hash value, through prev[]). The longest copy
 *     found is taken at once, at least 3 long (greedy parsing: zlib's lazy matching, which
 *     looks one byte ahead for a longer one, gains a few per cent for more code); a 3-byte
 *     copy only from within 4096 bytes, as zlib does, since a farther one costs about as
 *     much as three literals. Otherwise the byte goes as a literal.
 *   - Huffman coding, block by block (3.2.3): a block covers at most 65535 input bytes and
 *     is written as whichever of the three kinds costs fewest bits: stored (so incompressible
 *     data grows by 5 bytes a block at most), the fixed codes (3.2.6), or codes built from
 *     the block's own symbol counts (3.2.7) by Huffman's construction, with the counts
 *     flattened until no code is longer than deflate allows.
 * Huffman codes are packed from their first bit on and every other field from its lowest
 * bit (3.1.1), so each code is kept bit-reversed and everything goes out through put_bits().
 * The tables of 3.2.5 to 3.2.7 are inflate.c's (inflate.h), so both sides read one copy.
 */
#include "deflate.h"

#include <stdint.h>
#include <string.h>

#include "alloc.h"
#include "inflate.h"

#define WINDOW 32768      /* the farthest back a copy reaches (3.2.5)                 */
#define MIN_MATCH 3       /* the shortest copy deflate codes                          */
#define MAX_MATCH 258     /* the longest                                              */
#define FAR_FOR_3 4096    /* a 3-byte copy from farther back is not worth its bits    */
#define MAX_CHAIN 64      /* earlier positions tried for each position: bounded time  */
#define HASH_BITS 15
#define BLOCK_BYTES 65535 /* one block's input: at most one stored block's LEN        */
#define MAX_CL_BITS 7     /* the code-length code's lengths are sent in 3 bits        */
#define N_SYMBOLS DEFLATE_N_LITLEN
#define N_USED_LITLEN 286 /* 286 and 287 take part in the fixed code only             */

/* Extra bits after the code-length symbols 16, 17 and 18 (3.2.7). */
static const int run_extra_bits[3] = {2, 3, 7};

/* A copy (distance > 0: length bytes from distance back) or a literal (distance 0, the byte
 * in length). */
struct token {
    unsigned short length, distance;
};

/* A Huffman code: each symbol's code length (0: unused) and its code, bit-reversed. */
struct code {
    unsigned char length[N_SYMBOLS];
    unsigned short bits[N_SYMBOLS];
};

/* The output: bits waiting to make a byte, and whether the stream outgrew capacity. */
struct writer {
    unsigned char *out;
    size_t capacity, at;
    uint32_t bits;
    int n_bits, full;
};

/* One compression's state, allocated once by zlib_deflate(), its one owner. */
struct deflate {
    const unsigned char *in;
    size_t in_size;
    size_t head[1 << HASH_BITS]; /* each hash's latest position + 1; 0: none yet      */
    size_t prev[WINDOW];         /* at p % WINDOW: the position + 1 before p of p's hash */
    struct token tokens[BLOCK_BYTES];
    size_t n_tokens;
    struct writer w;
};

/* ---- bits ------------------------------------------------------------------------------ */

static void put_byte(struct writer *w, unsigned byte)
{
    if (w->at == w->capacity)
        w->full = 1;
    else
        w->out[w->at++] = (unsigned char)byte;
}

/* The n (0..16) bits of value, its lowest bit first (3.1.1). */
static void put_bits(struct writer *w, unsigned value, int n)
{
    w->bits |= (uint32_t)value << w->n_bits;
    w->n_bits += n;
    while (w->n_bits >= 8) {
        put_byte(w, (unsigned)(w->bits & 0xFF));
        w->bits >>= 8;
        w->n_bits -= 8;
    }
}

/* Zero bits up to the next byte boundary. */
static void align(struct writer *w)
{
    if (w->n_bits > 0)
        put_bits(w, 0, 8 - w->n_bits);
}

/* ---- LZ77 ------------------------------------------------------------------------------ */

/* A hash of the three bytes at p: Knuth's multiplicative hashing, the top HASH_BITS bits. */
static unsigned hash3(const unsigned char *p)
{
    uint32_t v = (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
    return (unsigned)((uint32_t)(v * UINT32_C(2654435761)) >> (32 - HASH_BITS));
}

/* Puts position p (three bytes follow it) at the head of its hash's chain. */
static void insert(struct deflate *d, size_t p)
{
    unsigned h = hash3(d->in + p);
    d->prev[p % WINDOW] = d->head[h];
    d->head[h] = p + 1;
}

/* The longest copy of the bytes at p, at most max_length long, among the positions of p's
 * chain (latest first, so ties go to the nearest): its length and *distance, or 0 (and
 * *distance untouched) when no copy is worth taking. The chain only goes back, and stops
 * past the window: a prev[] entry is overwritten only by a position WINDOW later, which is
 * not yet in the chain. */
static size_t find_match(const struct deflate *d, size_t p, size_t max_length,
                         size_t *distance)
{
    size_t best = 0, best_distance = 0, candidate = d->head[hash3(d->in + p)];
    for (int tried = 0; candidate != 0 && tried < MAX_CHAIN; tried++) {
        size_t c = candidate - 1, n = 0;
        if (p - c > WINDOW)
            break;
        while (n < max_length && d->in[c + n] == d->in[p + n])
            n++;
        if (n > best) {
            best = n;
            best_distance = p - c;
            if (n == max_length)
                break;
        }
        candidate = d->prev[c % WINDOW];
    }
    if (best < MIN_MATCH || (best == MIN_MATCH && best_distance > FAR_FOR_3))
        return 0;
    *distance = best_distance;
    return best;
}

/* The tokens of the block starting at input position start, covering at most BLOCK_BYTES
 * bytes (no copy crosses its end, so a stored block could hold it): the block's end. */
static size_t tokenize(struct deflate *d, size_t start)
{
    size_t end = d->in_size - start < BLOCK_BYTES ? d->in_size : start + BLOCK_BYTES;
    size_t p = start;
    d->n_tokens = 0;
    while (p < end) {
        size_t distance = 0, max = end - p < MAX_MATCH ? end - p : MAX_MATCH;
        size_t length = max >= MIN_MATCH ? find_match(d, p, max, &distance) : 0;
        struct token *t = &d->tokens[d->n_tokens++];
        t->length = (unsigned short)(length > 0 ? length : d->in[p]);
        t->distance = (unsigned short)distance;
        size_t taken = length > 0 ? length : 1;
        for (size_t i = 0; i < taken; i++)
            if (p + i + MIN_MATCH <= d->in_size)
                insert(d, p + i);
        p += taken;
    }
    return end;
}

/* ---- Huffman codes --------------------------------------------------------------------- */

/* The symbol a length or distance falls under: the last of the n bases not above it. */
static int symbol_of(const short *base, int n, int value)
{
    int i = n - 1;
    while (base[i] > value)
        i--;
    return i;
}

/* The lightest tree still to be joined, the first made or counted among equals. */
static int lightest(const unsigned long *weight, const char *alive, int n_nodes)
{
    int best = -1;
    for (int i = 0; i < n_nodes; i++)
        if (alive[i] && (best < 0 || weight[i] < weight[best]))
            best = i;
    return best;
}

/* Huffman's construction over the n counts (a symbol counted 0 takes no part): the two
 * lightest trees are joined until one is left; node n + k is the k-th join. Fills
 * parent[] (-1: the root, or a symbol not in the tree); returns the number of nodes. */
static int huffman_tree(const unsigned long *count, int n, int *parent)
{
    unsigned long weight[2 * N_SYMBOLS];
    char alive[2 * N_SYMBOLS];
    int n_nodes = n, n_alive = 0;
    for (int i = 0; i < 2 * n; i++)
        parent[i] = -1;
    for (int i = 0; i < n; i++) {
        weight[i] = count[i];
        alive[i] = count[i] > 0;
        n_alive += alive[i];
    }
    for (; n_alive > 1; n_alive--) {
        int a = lightest(weight, alive, n_nodes);
        alive[a] = 0;
        int b = lightest(weight, alive, n_nodes);
        alive[b] = 0;
        weight[n_nodes] = weight[a] + weight[b];
        alive[n_nodes] = 1;
        parent[a] = parent[b] = n_nodes++;
    }
    return n_nodes;
}

/* Code lengths of at most max_bits for the n symbols counted in count[] (3.2.2's
 * canonical code is then fixed by the lengths alone): each symbol's depth in Huffman's
 * tree. While the tree is too deep, every count above 1 is halved (plus one) and the tree
 * built again: the counts approach each other, and equal counts give a balanced tree. At
 * least two symbols get a code (a lone one pairs with the first uncounted symbol), so
 * that every code is complete, as zlib's inflate requires. */
static void huffman_lengths(const unsigned long *count, int n, int max_bits,
                            unsigned char *length)
{
    unsigned long weight[N_SYMBOLS];
    int parent[2 * N_SYMBOLS], depth[2 * N_SYMBOLS], used = 0;
    for (int i = 0; i < n; i++) {
        weight[i] = count[i];
        used += count[i] > 0;
    }
    for (int i = 0; i < n && used < 2; i++)
        if (weight[i] == 0) {
            weight[i] = 1;
            used++;
        }
    for (;;) {
        int n_nodes = huffman_tree(weight, n, parent), deepest = 0;
        for (int i = n_nodes - 1; i >= 0; i--) /* a parent is made after its children */
            depth[i] = parent[i] < 0 ? 0 : depth[parent[i]] + 1;
        for (int i = 0; i < n; i++)
            deepest = depth[i] > deepest ? depth[i] : deepest;
        if (deepest <= max_bits) {
            for (int i = 0; i < n; i++)
                length[i] = (unsigned char)depth[i];
            return;
        }
        for (int i = 0; i < n; i++)
            weight[i] = weight[i] > 1 ? weight[i] / 2 + 1 : weight[i];
    }
}

/* The codes of the canonical Huffman code with c's lengths (3.2.2), bit-reversed: the
 * codes of each length are consecutive, in the order of their symbols, and follow the
 * shorter ones. */
static void assign_codes(struct code *c, int n)
{
    int count[DEFLATE_MAX_BITS + 1] = {0};
    unsigned next[DEFLATE_MAX_BITS + 1], code = 0;
    for (int i = 0; i < n; i++)
        count[c->length[i]]++;
    count[0] = 0;
    for (int bits = 1; bits <= DEFLATE_MAX_BITS; bits++) {
        code = (code + (unsigned)count[bits - 1]) << 1;
        next[bits] = code;
    }
    for (int i = 0; i < n; i++) {
        int len = c->length[i];
        unsigned v = len > 0 ? next[len]++ : 0, reversed = 0;
        for (int b = 0; b < len; b++)
            reversed |= (v >> b & 1u) << (len - 1 - b);
        c->bits[i] = (unsigned short)reversed;
    }
}

/* ---- blocks ---------------------------------------------------------------------------- */

/* How often each symbol occurs in the block's tokens (the end of block once), and the
 * extra bits of their lengths and distances. */
struct counts {
    unsigned long litlen[N_SYMBOLS], dist[DEFLATE_N_DIST], extra_bits;
};

/* A block's codes; for a dynamic block also the code-length code and the lengths of the
 * other two as its symbols (run_symbol, each with the value of its extra bits). */
struct block_codes {
    struct code litlen, dist, cl;
    int hlit, hdist, hclen, n_runs;
    unsigned char run_symbol[N_USED_LITLEN + DEFLATE_N_DIST];
    unsigned char run_extra[N_USED_LITLEN + DEFLATE_N_DIST];
};

static void count_symbols(const struct deflate *d, struct counts *c)
{
    memset(c, 0, sizeof *c);
    for (size_t i = 0; i < d->n_tokens; i++) {
        const struct token *t = &d->tokens[i];
        if (t->distance == 0) {
            c->litlen[t->length]++;
            continue;
        }
        int l = symbol_of(deflate_length_base, DEFLATE_N_LENGTHS, t->length);
        int s = symbol_of(deflate_dist_base, DEFLATE_N_DIST, t->distance);
        c->litlen[DEFLATE_END_OF_BLOCK + 1 + l]++;
        c->dist[s]++;
        c->extra_bits += (unsigned long)(deflate_length_extra[l] + deflate_dist_extra[s]);
    }
    c->litlen[DEFLATE_END_OF_BLOCK] = 1;
}

/* The lengths of a dynamic block's codes as the symbols of 3.2.7: 0..15 a length, 16 the
 * previous length 3..6 times more, 17 and 18 a zero 3..10 and 11..138 times. How many. */
static int run_lengths(const unsigned char *length, int n, unsigned char *symbol,
                       unsigned char *extra)
{
    int k = 0, previous = -1;
    for (int i = 0; i < n; k++) {
        int run = 1;
        while (i + run < n && length[i + run] == length[i])
            run++;
        if (length[i] == 0 && run >= 3) {
            run = run > 138 ? 138 : run;
            symbol[k] = run >= 11 ? 18 : 17;
            extra[k] = (unsigned char)(run - (run >= 11 ? 11 : 3));
        } else if (length[i] == previous && run >= 3) {
            run = run > 6 ? 6 : run;
            symbol[k] = 16;
            extra[k] = (unsigned char)(run - 3);
        } else {
            run = 1;
            symbol[k] = length[i];
            extra[k] = 0;
        }
        previous = length[i];
        i += run;
    }
    return k;
}

static void fixed_codes(struct block_codes *b)
{
    deflate_fixed_lengths(b->litlen.length, b->dist.length);
    assign_codes(&b->litlen, N_SYMBOLS);
    assign_codes(&b->dist, DEFLATE_N_DIST);
}

/* Codes built from the block's counts, and the header that states them (3.2.7): HLIT and
 * HDIST leave off the trailing unused symbols, HCLEN the code-length code's last unused
 * lengths in deflate_code_length_order. */
static void dynamic_codes(const struct counts *c, struct block_codes *b)
{
    unsigned char lengths[N_USED_LITLEN + DEFLATE_N_DIST];
    unsigned long cl_count[DEFLATE_N_CODE_LENGTHS] = {0};
    memset(b->litlen.length, 0, sizeof b->litlen.length);
    huffman_lengths(c->litlen, N_USED_LITLEN, DEFLATE_MAX_BITS, b->litlen.length);
    huffman_lengths(c->dist, DEFLATE_N_DIST, DEFLATE_MAX_BITS, b->dist.length);
    assign_codes(&b->litlen, N_USED_LITLEN);
    assign_codes(&b->dist, DEFLATE_N_DIST);
    for (b->hlit = N_USED_LITLEN; b->litlen.length[b->hlit - 1] == 0; b->hlit--)
        continue; /* stops at the end of block, 256, at the latest */
    for (b->hdist = DEFLATE_N_DIST; b->dist.length[b->hdist - 1] == 0; b->hdist--)
        continue; /* two distance symbols have a code at least */
    memcpy(lengths, b->litlen.length, (size_t)b->hlit);
    memcpy(lengths + b->hlit, b->dist.length, (size_t)b->hdist);
    b->n_runs = run_lengths(lengths, b->hlit + b->hdist, b->run_symbol, b->run_extra);
    for (int i = 0; i < b->n_runs; i++)
        cl_count[b->run_symbol[i]]++;
    huffman_lengths(cl_count, DEFLATE_N_CODE_LENGTHS, MAX_CL_BITS, b->cl.length);
    assign_codes(&b->cl, DEFLATE_N_CODE_LENGTHS);
    for (b->hclen = DEFLATE_N_CODE_LENGTHS;
         b->hclen > 4 && b->cl.length[deflate_code_length_order[b->hclen - 1]] == 0; b->hclen--)
        continue;
}

/* The bits of the block's symbols and extra bits under b's codes. */
static unsigned long data_bits(const struct counts *c, const struct block_codes *b)
{
    unsigned long bits = c->extra_bits;
    for (int i = 0; i < N_SYMBOLS; i++)
        bits += c->litlen[i] * b->litlen.length[i];
    for (int i = 0; i < DEFLATE_N_DIST; i++)
        bits += c->dist[i] * b->dist.length[i];
    return bits;
}

/* The bits of a dynamic block's header after its first three. */
static unsigned long dynamic_header_bits(const struct block_codes *b)
{
    unsigned long bits = 5 + 5 + 4 + 3 * (unsigned long)b->hclen;
    for (int i = 0; i < b->n_runs; i++) {
        int s = b->run_symbol[i];
        bits += b->cl.length[s] + (unsigned long)(s >= 16 ? run_extra_bits[s - 16] : 0);
    }
    return bits;
}

static void put_symbol(struct writer *w, const struct code *c, int symbol)
{
    put_bits(w, c->bits[symbol], c->length[symbol]);
}

static void put_dynamic_header(struct writer *w, const struct block_codes *b)
{
    put_bits(w, (unsigned)(b->hlit - 257), 5);
    put_bits(w, (unsigned)(b->hdist - 1), 5);
    put_bits(w, (unsigned)(b->hclen - 4), 4);
    for (int i = 0; i < b->hclen; i++)
        put_bits(w, b->cl.length[deflate_code_length_order[i]], 3);
    for (int i = 0; i < b->n_runs; i++) {
        int s = b->run_symbol[i];
        put_symbol(w, &b->cl, s);
        if (s >= 16)
            put_bits(w, b->run_extra[i], run_extra_bits[s - 16]);
    }
}

/* The block's tokens, then its end, in b's codes (3.2.5). */
static void put_tokens(struct deflate *d, const struct block_codes *b)
{
    for (size_t i = 0; i < d->n_tokens; i++) {
        const struct token *t = &d->tokens[i];
        if (t->distance == 0) {
            put_symbol(&d->w, &b->litlen, t->length);
            continue;
        }
        int l = symbol_of(deflate_length_base, DEFLATE_N_LENGTHS, t->length);
        int s = symbol_of(deflate_dist_base, DEFLATE_N_DIST, t->distance);
        put_symbol(&d->w, &b->litlen, DEFLATE_END_OF_BLOCK + 1 + l);
        put_bits(&d->w, (unsigned)(t->length - deflate_length_base[l]), deflate_length_extra[l]);
        put_symbol(&d->w, &b->dist, s);
        put_bits(&d->w, (unsigned)(t->distance - deflate_dist_base[s]), deflate_dist_extra[s]);
    }
    put_symbol(&d->w, &b->litlen, DEFLATE_END_OF_BLOCK);
}

/* A stored block (3.2.4): its 3 header bits, zeros to the byte's end, LEN and its ones'
 * complement NLEN (16 bits each), the bytes. */
static void put_stored(struct writer *w, const unsigned char *bytes, size_t n, int last)
{
    put_bits(w, (unsigned)last, 1);
    put_bits(w, 0, 2);
    align(w);
    put_bits(w, (unsigned)n, 16);
    put_bits(w, (unsigned)~n & 0xFFFFu, 16);
    for (size_t i = 0; i < n && !w->full; i++)
        put_byte(w, bytes[i]);
}

/* The block of input [start, end), whose tokens d holds, in whichever kind costs fewest
 * bits; among equals the simpler: stored, then fixed. */
static void put_block(struct deflate *d, size_t start, size_t end, int last)
{
    struct counts c;
    struct block_codes fixed, dynamic;
    count_symbols(d, &c);
    fixed_codes(&fixed);
    dynamic_codes(&c, &dynamic);
    unsigned long fixed_bits = data_bits(&c, &fixed);
    unsigned long dynamic_bits = dynamic_header_bits(&dynamic) + data_bits(&c, &dynamic);
    unsigned long stored_bits = (unsigned long)(8 - (d->w.n_bits + 3) % 8) % 8 + 32 +
                                8 * (unsigned long)(end - start);
    if (stored_bits <= fixed_bits && stored_bits <= dynamic_bits) {
        put_stored(&d->w, d->in + start, end - start, last);
        return;
    }
    const struct block_codes *b = dynamic_bits < fixed_bits ? &dynamic : &fixed;
    put_bits(&d->w, (unsigned)last, 1);
    put_bits(&d->w, b == &dynamic ? 2 : 1, 2); /* BTYPE 10: dynamic codes, 01: fixed */
    if (b == &dynamic)
        put_dynamic_header(&d->w, b);
    put_tokens(d, b);
}

/* ---- the zlib stream ------------------------------------------------------------------- */

size_t zlib_deflate(const unsigned char *in, size_t in_size, unsigned char *out,
                    size_t capacity)
{
    struct deflate *d = xmalloc(1, sizeof *d, "a deflate stream");
    struct writer w = {out, capacity, 0, 0, 0, 0};
    memset(d->head, 0, sizeof d->head);
    d->in = in;
    d->in_size = in_size;
    d->w = w;
    /* RFC 1950 2.2: CMF 0x78 (method 8, deflate, with a 32 KiB window), FLG 0x01 (no preset
     * dictionary, level "fastest"), CMF * 256 + FLG a multiple of 31. */
    put_byte(&d->w, 0x78);
    put_byte(&d->w, 0x01);
    size_t start = 0;
    do {
        size_t end = tokenize(d, start);
        put_block(d, start, end, end == in_size);
        start = end;
    } while (start < in_size && !d->w.full);
    align(&d->w);
    unsigned long adler = adler32(in, in_size); /* high byte first, as all of RFC 1950 */
    for (int i = 3; i >= 0; i--)
        put_byte(&d->w, (unsigned)(adler >> (8 * i) & 0xFF));
    size_t size = d->w.full ? 0 : d->w.at;
    xfree(d);
    return size;
}

/* Each block no longer than its stored form (put_block), which is the bytes, 5 more a block
 * (3 bits, padding, LEN, NLEN), the zlib header and checksum 6 in all. */
size_t zlib_deflate_bound(size_t in_size)
{
    return in_size + 5 * (in_size / BLOCK_BYTES + 1) + 6;
}
