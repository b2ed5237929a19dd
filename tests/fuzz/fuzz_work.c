/*
 * tests/fuzz/fuzz_work.c -- libFuzzer target for the work file's reader (app/work_file.c,
 * --load-photons), built by `make fuzz`; a development tool only.
 *
 * The reader refuses a file saved for another render by its hash (bytes 12 to 19, lowest
 * first), which a fuzzer would not guess, so the hash expected is the one the input holds;
 * and it refuses a file whose checksum (its last 8 bytes) is wrong, which a fuzzer would
 * not guess either, so the checksum is made right for every input. So every input's values
 * reach the range checks (work_file.h), as a file crafted by hand would: an input the
 * reader takes must hold only values in range, and saving what was read must give back
 * the input's bytes; either failing aborts, as a crash, a sanitizer report or a leak on
 * the way does: each is a bug.
 *   build/fuzz/fuzz_work CORPUS_DIR tests/fuzz/seeds/work
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/app/work_file.h"
#include "../../src/base/hash.h"
#include "../../src/base/output.h"
#include "input.h"

#define CHECKSUM_BYTES 8

/* Whether every photon and record of work is in work_file.h's ranges. */
static int in_range(const struct global_work *work)
{
    for (size_t m = 0; m < work->n_maps; m++)
        for (size_t i = 1; work->maps[m] != NULL && i <= work->maps[m]->n_photons; i++) {
            const struct photon *p = &work->maps[m]->photons[i];
            struct vec3 power = photon_power(p);
            if (!isfinite(p->pos[0]) || !isfinite(p->pos[1]) || !isfinite(p->pos[2]) ||
                !(vec3_max_component(power) <= WORK_PHOTON_POWER_MAX) ||
                (p->flags & ~(15u | PHOTON_BACK)) != 0)
                return 0;
        }
    for (size_t i = 0; i < work->n_records; i++) {
        const struct irradiance_record *r = &work->records[i];
        if (!(r->e.x >= 0 && r->e.y >= 0 && r->e.z >= 0 && r->r > 0 &&
              fabs(vec3_length(r->n) - 1) < 1e-6))
            return 0;
    }
    return 1;
}

/* Whether file name holds exactly the size bytes of data. */
static int holds(const char *name, const uint8_t *data, size_t size)
{
    FILE *f = fopen(name, "rb");
    uint8_t *back = malloc(size + 1);
    size_t n = f != NULL && back != NULL ? fread(back, 1, size + 1, f) : 0;
    int same = n == size && memcmp(back, data, size) == 0;
    free(back);
    if (f != NULL)
        fclose(f);
    return same;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint64_t hash = 0;
    for (int i = 7; i >= 0 && size >= 20; i--)
        hash = hash << 8 | data[12 + i];
    uint8_t *bytes = malloc(size + 1);
    if (bytes == NULL)
        abort();
    memcpy(bytes, data, size);
    if (size > CHECKSUM_BYTES) {
        uint64_t sum = fnv1a(FNV1A_OFFSET_BASIS, bytes, size - CHECKSUM_BYTES);
        for (int i = 0; i < CHECKSUM_BYTES; i++)
            bytes[size - CHECKSUM_BYTES + i] = (uint8_t)(sum >> (8 * i));
    }
    const char *name = input_file(bytes, size);
    struct global_work work;
    memset(&work, 0, sizeof work);
    struct error err;
    if (work_file_read(name, hash, &work, &err) == 0) {
        char back[FILENAME_MAX];
        snprintf(back, sizeof back, "%s.back", name);
        if (!in_range(&work) || work_file_write(back, hash, &work, &err) != 0 ||
            !holds(back, bytes, size))
            abort();
        remove(back);
    }
    global_work_free(&work);
    free(bytes);
    outputs_abandon(); /* forgets the input, so the registry does not grow */
    return 0;
}
