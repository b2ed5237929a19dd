/*
 * tests/tests.h -- one entry point per room's test file (tests/test_<room>.c).
 */
#ifndef PHOTON_TESTS_H
#define PHOTON_TESTS_H

#include "check.h"

void test_base(struct check *t);   /* test_base.c: rng, allocation, errors       */
void test_image(struct check *t);  /* test_image.c: PFM/PPM, compare metrics      */
void test_png(struct check *t);    /* test_png.c: PNG files, outside readers      */
void test_convert(struct check *t); /* test_convert.c: photon convert, compare --diff's picture */
void test_exr(struct check *t);    /* test_exr.c: OpenEXR files, inflate          */
void test_deflate(struct check *t); /* test_deflate.c: deflate through our inflate */
void test_compare(struct check *t); /* test_compare.c: per-pixel statistical test */
void test_plot(struct check *t);   /* test_plot.c: CSV reading, SVG plots         */
void test_geom(struct check *t);   /* test_geom.c: the BVH against brute force    */
void test_geom_primitives(struct check *t); /* test_geom_primitives.c: spheres, triangles, quads */
void test_bvh(struct check *t);    /* test_bvh.c: the float box test, wide nodes, mesh */
void test_scene(struct check *t);  /* test_scene.c: parser, camera, lights        */
void test_brdf(struct check *t);   /* test_brdf.c: the models' samplers, energy   */
void test_brdf_glass(struct check *t); /* test_brdf_glass.c: glass's optics, delta lobes */
void test_brdf_conventions(struct check *t); /* test_brdf_conventions.c: every model's edges */
void test_shapes(struct check *t); /* test_shapes.c: the sphere flake             */
void test_shapes_heightfield(struct check *t); /* test_shapes_heightfield.c: noise, heightfield */
void test_import(struct check *t); /* test_import.c: NFF, OBJ, scene keywords     */
void test_import_geom(struct check *t); /* test_import_geom.c: the cone, ear clipping */
void test_import_obj(struct check *t); /* test_import_obj.c: obj rotate, usemtl */
void test_photon(struct check *t); /* test_photon.c: photon record, kd-tree       */
void test_hit_points(struct check *t); /* test_hit_points.c: 2008's hit-point tree  */
void test_trace_emission(struct check *t); /* test_trace_emission.c: photon emission */
void test_trace(struct check *t);  /* test_trace.c: photon tracing, path classes  */
void test_trace_estimates(struct check *t); /* test_trace_estimates.c: estimates, maps */
void test_trace_photons_mode(struct check *t); /* test_trace_photons_mode.c: --mode photons */
void test_precomputed(struct check *t); /* test_precomputed.c: irradiance at photons */
void test_projection(struct check *t); /* test_projection.c: projection maps (1994) */
void test_projection_cells(struct check *t); /* test_projection_cells.c: the maps' cells */
void test_ppm(struct check *t);    /* test_ppm.c: progressive photon mapping      */
void test_cache(struct check *t);  /* test_cache.c: irradiance cache records      */
void test_cache_lookup(struct check *t); /* test_cache_lookup.c: the cache's lookups */
void test_render(struct check *t); /* test_render.c: direct mode, crops, scaling, adaptive */
void test_pt(struct check *t);     /* test_pt.c: the path tracer, closed forms    */
void test_jensen1994(struct check *t); /* test_jensen1994.c: --mode 1994             */
void test_jensen1994_caustics(struct check *t); /* test_jensen1994_caustics.c: its caustics */
void test_jensen1996(struct check *t); /* test_jensen1996.c: --mode 1996, photon maps */
void test_report(struct check *t); /* test_report.c: --report, --time-limit, ...  */
void test_merge(struct check *t);  /* test_merge.c: tile records, photon merge      */
void test_merge_work_file(struct check *t); /* test_merge_work_file.c: the work file's bytes */
void test_cli(struct check *t);    /* test_cli.c: the command line, exit statuses */
void test_progress(struct check *t); /* test_progress.c: the progress line, its forecast */
void test_docs(struct check *t);   /* test_docs.c: the documentation against the product */
void test_spd(struct check *t);    /* test_spd.c: all 22 SPD files (PHOTON_SPD), by name only */
void test_presets(struct check *t); /* test_presets.c: --quality's presets         */
void test_paper(struct check *t);  /* test_paper.c: --paper and its switches       */
void test_tte_fit(struct check *t); /* test_tte_fit.c: make bench's fit of pt's error */
void test_ppm_departures(struct check *t); /* test_ppm_departures.c: 2008's departures */
void test_sppm(struct check *t);    /* test_sppm.c: --mode 2009, stochastic PPM        */
void test_literal(struct check *t); /* test_literal.c: 1994, 2008, 2009 --paper against the papers written out */
void test_export(struct check *t);  /* test_export.c: photon export to pbrt-v4, Mitsuba 3 */
void test_switches(struct check *t); /* test_switches.c: each paper switch of 1994, 1996 */
void test_export_blender(struct check *t); /* test_export_blender.c: the Blender script */
void test_export_output(struct check *t); /* test_export_output.c: size, -o's ending */
void test_help(struct check *t); /* test_help.c: --help's first screen, --help all */
void test_outputs(struct check *t); /* test_outputs.c: outputs and inputs of a command */
void test_foreign_files(struct check *t); /* test_foreign_files.c: files photon did not make */
void test_numbers(struct check *t); /* test_numbers.c: numbers, ranges, messages       */
void test_number_syntax(struct check *t); /* test_number_syntax.c: every reader, one syntax */
void test_given_once(struct check *t); /* test_given_once.c: an option given twice */
void test_messages(struct check *t); /* test_messages.c: what photon prints */
void test_sky(struct check *t);     /* test_sky.c: the background as a light, every mode */
void test_error(struct check *t);   /* test_error.c: error images against closed forms */
void test_error_2009(struct check *t); /* test_error_2009.c: 2009's error images, the same */
void test_error_photons(struct check *t); /* test_error_photons.c: the photons mode's */
void test_error_2008(struct check *t); /* test_error_2008.c: 2008's error images, the same */
void test_compare_verdict(struct check *t); /* test_compare_verdict.c: compare's block test */
void test_shading(struct check *t); /* test_shading.c: shading normals, every mode */
void test_lens(struct check *t);    /* test_lens.c: the thin lens, its sequence, the defocused edge */

#endif
