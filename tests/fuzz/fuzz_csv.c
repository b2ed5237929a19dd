/*
 * tests/fuzz/fuzz_csv.c -- libFuzzer target for photon plot's CSV reader (image/csv.c),
 * built by `make fuzz`; a development tool only. Every row is read to the end of the file
 * or the first error.
 *   build/fuzz/fuzz_csv CORPUS_DIR tests/fuzz/seeds/csv
 */
#include <stdint.h>

#include "../../src/base/output.h"
#include "../../src/image/csv.h"
#include "input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct csv csv;
    struct error err;
    if (csv_open(&csv, input_file(data, size), &err) == 0) {
        double row[CSV_FIELDS_MAX];
        while (csv_next_row(&csv, row, &err) > 0)
            ;
        csv_close(&csv);
    }
    outputs_abandon();
    return 0;
}
