/*
 * tests/bench/bench.h -- `make bench`: figures, never verdicts.
 *
 * Each workload prints "name=value" lines, medians of BENCH_REPEATS runs, with the
 * checksums that show the work was the same. Times are CPU seconds from clock(): the
 * program is single-threaded, and figures mean something only as ratios within one run.
 */
#ifndef PHOTON_BENCH_H
#define PHOTON_BENCH_H

#define BENCH_REPEATS 3 /* bench/README.md: the median of at least 3 repetitions */

double bench_seconds(void);                       /* CPU seconds since start */
double bench_median(double *values, int count);   /* sorts values in place   */

struct scene;
/* The scene file at path, finished at its own image size; NULL (the error printed) when it
 * cannot be read. The caller frees it with scene_free(). */
struct scene *bench_scene(const char *path);

void bench_rays(void);   /* bench_rays.c: bench/README.md, rays on generated and shipped scenes */
void bench_knn(void);    /* bench_knn.c: bench/README.md, knn, Cornell-wall k-nearest          */
void bench_shapes(void); /* bench_shapes.c: procedural objects against their expansions   */
void bench_photons(void); /* bench_photons.c: photons traced and stored per second        */
void bench_ppm(void);     /* bench_ppm.c: --mode 2008 hit points and photons per second    */
void bench_tte(void);     /* bench_tte.c: bench/README.md, tte, time to error beside pt         */
void bench_tts(void);     /* bench_tts.c: time to a stated error, pt, 2008, 2009 (tts.sh)  */
void bench_tiles(void);   /* bench_tiles.c: 2 tile processes against 1, wall time (tiles.sh) */

#endif
