/*
 * tests/tests.h -- one entry point per room's test file (tests/test_<room>.c).
 */
#ifndef PHOTON_TESTS_H
#define PHOTON_TESTS_H

#include "check.h"

void test_base(struct check *t);   /* test_base.c: rng, allocation, errors       */
void test_image(struct check *t);  /* test_image.c: PFM/PPM, compare metrics      */
void test_png(struct check *t);    /* test_png.c: PNG files, outside readers      */
void test_compare(struct check *t); /* test_compare.c: per-pixel statistical test */
void test_plot(struct check *t);   /* test_plot.c: CSV reading, SVG plots         */
void test_geom(struct check *t);   /* test_geom.c: primitives, BVH, robustness    */
void test_bvh(struct check *t);    /* test_bvh.c: the float box test, wide nodes, mesh */
void test_scene(struct check *t);  /* test_scene.c: parser, camera, lights        */
void test_brdf(struct check *t);   /* test_brdf.c: the material models            */
void test_shapes(struct check *t); /* test_shapes.c: sphere flake, heightfield    */
void test_import(struct check *t); /* test_import.c: cone, ear clipping, NFF, OBJ */
void test_photon(struct check *t); /* test_photon.c: photon record, kd-tree       */
void test_hit_points(struct check *t); /* test_hit_points.c: 2008's hit-point tree  */
void test_trace(struct check *t);  /* test_trace.c: emission, tracing, estimates  */
void test_precomputed(struct check *t); /* test_precomputed.c: irradiance at photons */
void test_projection(struct check *t); /* test_projection.c: projection maps (1994) */
void test_ppm(struct check *t);    /* test_ppm.c: progressive photon mapping      */
void test_cache(struct check *t);  /* test_cache.c: irradiance cache, gradients   */
void test_render(struct check *t); /* test_render.c: direct mode, crops, scaling, adaptive */
void test_pt(struct check *t);     /* test_pt.c: the path tracer, closed forms    */
void test_jensen1994(struct check *t); /* test_jensen1994.c: --mode 1994             */
void test_jensen1996(struct check *t); /* test_jensen1996.c: --mode 1996, photon maps */
void test_report(struct check *t); /* test_report.c: --report, --time-limit, ...  */
void test_merge(struct check *t);  /* test_merge.c: tile records, photon merge      */
void test_cli(struct check *t);    /* test_cli.c: the command line, exit statuses */
void test_docs(struct check *t);   /* test_docs.c: the documentation against the product */
void test_spd(struct check *t);    /* test_spd.c: all 22 SPD files (PHOTON_SPD), by name only */
void test_presets(struct check *t); /* test_presets.c: --quality's presets         */
void test_paper(struct check *t);  /* test_paper.c: --paper and its switches       */
void test_tte_fit(struct check *t); /* test_tte_fit.c: make bench's fit of pt's error */
void test_ppm_departures(struct check *t); /* test_ppm_departures.c: 2008's departures */
void test_sppm(struct check *t);    /* test_sppm.c: --mode 2009, stochastic PPM        */
void test_export(struct check *t);  /* test_export.c: photon export to pbrt-v4, Mitsuba 3 */
void test_switches(struct check *t); /* test_switches.c: each paper switch of 1994, 1996 */
void test_export_blender(struct check *t); /* test_export_blender.c: the Blender script */
void test_outputs(struct check *t); /* test_outputs.c: outputs and inputs of a command */
void test_numbers(struct check *t); /* test_numbers.c: numbers, ranges, messages       */
void test_sky(struct check *t);     /* test_sky.c: the background as a light, every mode */
void test_lens(struct check *t);    /* test_lens.c: the thin lens, its sequence, the defocused edge */

#endif
