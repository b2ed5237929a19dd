/*
 * tests/fuzz/input.h -- what every fuzz target shares: the readers take file names, so
 * each input goes to a file first.
 */
#ifndef PHOTON_FUZZ_INPUT_H
#define PHOTON_FUZZ_INPUT_H

#include <stddef.h>
#include <stdint.h>

/* The fuzzer's entry point, declared once for the targets' definitions. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Writes the bytes to this process's own temporary file (named on the first call,
 * removed at exit), so fuzzers running side by side never share one; returns its name. */
const char *input_file(const uint8_t *data, size_t size);

#endif
