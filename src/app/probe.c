/*
 * app/probe.c -- `photon probe` (probe.h): the irradiance along a line, exact where the
 * scene allows, and from mode 1994's photon map with and without differential checking.
 */
#include "probe.h"

#include <stdio.h>
#include <string.h>

#include "../base/option_once.h"
#include "../base/output.h"
#include "../image/csv.h"
#include "../modes/jensen1994_maps.h"
#include "../modes/photons.h"
#include "../photon/estimate.h"
#include "../photon/illumination_map.h"
#include "../photon/kdtree.h"
#include "../photon/trace.h"
#include "../scene/brdf.h"
#include "option_values.h"

#define PROBE_DEFAULT_GATHER 200      /* the paper's Fig. 8: "200 photons per estimate"  */
#define PROBE_DEFAULT_PHOTONS 1000000 /* light rays: reference/fig8-*.svg were made with
                                         them (1994 renders default to more)            */
#define PROBE_MAX_SAMPLES 1000000
/* The usage in two parts: one line in a message, two in --help (within 100 columns). */
#define PROBE_USAGE_NAMES "usage: photon probe SCENE --line X0 Y0 Z0 X1 Y1 Z1 --samples N " \
                          "-o FILE.csv"
#define PROBE_USAGE_OPTIONS "[--normal NX NY NZ] [--photons N] [--gather N] [--differential R] " \
                            "[--seed S]"
#define PROBE_USAGE PROBE_USAGE_NAMES " " PROBE_USAGE_OPTIONS

struct probe_args {
    const char *scene_path, *output;
    double line[6];   /* a, then b */
    double normal[3]; /* of the surface the line lies on */
    int samples;
    uint64_t seed;
    struct jensen1994_settings settings;
};

const struct option_arity probe_options[] = {
    {"--line", 6},   {"--normal", 3}, {"--samples", 1},      {"-o", 1},    {"--seed", 1},
    {"--photons", 1}, {"--gather", 1}, {"--differential", 1}, {"--help", 0}, {NULL, 0},
};

/* Reads count numbers after argv[*i] into values, advancing *i. */
static int read_numbers(int argc, char **argv, int *i, int count, double *values,
                        struct error *err)
{
    const char *name = argv[*i];
    for (int k = 0; k < count; k++) {
        (*i)++;
        if (read_number(name, *i < argc ? argv[*i] : NULL, -1e30, 1e30, NUMBER_REAL,
                        &values[k], err) < 0)
            return -1;
    }
    return 0;
}

/* One option at argv[*i] (advancing *i past its values); -1 with *err when unknown. */
static int read_probe_option(int argc, char **argv, int *i, struct probe_args *args,
                             struct option_once *once, struct error *err)
{
    const char *name = argv[*i];
    const char *value = *i + 1 < argc ? argv[*i + 1] : NULL;
    double v = 0;
    int status = 0;
    int n_values = strcmp(name, "--line") == 0 ? 6 : strcmp(name, "--normal") == 0 ? 3 : 1;
    if (option_once(once, "probe", argc, argv, *i, n_values, err) < 0) /* all have values */
        return -1;
    if (strcmp(name, "--line") == 0)
        return read_numbers(argc, argv, i, 6, args->line, err);
    if (strcmp(name, "--normal") == 0)
        return read_numbers(argc, argv, i, 3, args->normal, err);
    (*i)++;
    if (strcmp(name, "-o") == 0)
        args->output = value;
    else if (strcmp(name, "--seed") == 0)
        return read_seed(value, &args->seed, err);
    else if (strcmp(name, "--samples") == 0 &&
             (status = read_number(name, value, 2, PROBE_MAX_SAMPLES, NUMBER_WHOLE, &v,
                                   err)) == 0)
        args->samples = (int)v;
    else if (strcmp(name, "--photons") == 0 &&
             (status = read_number(name, value, 1, MAX_PHOTONS, NUMBER_WHOLE, &v, err)) == 0)
        args->settings.n_photons = (size_t)v;
    else if (strcmp(name, "--gather") == 0 &&
             (status = read_number(name, value, 1, 100000, NUMBER_WHOLE, &v, err)) == 0)
        args->settings.gather = (size_t)v;
    else if (strcmp(name, "--differential") == 0 &&
             (status = read_number(name, value, 0, 100000, NUMBER_WHOLE, &v, err)) == 0)
        args->settings.differential_run = (int)v;
    else if (status == 0)
        return error_set(err, "", 0, "probe: unknown option '%s'; " PROBE_USAGE, name);
    return status;
}

/* The arguments after "probe"; 1 when --help was printed, -1 with *err filled. */
static int parse_probe_args(int argc, char **argv, struct probe_args *args, struct error *err)
{
    memset(args, 0, sizeof *args);
    args->scene_path = args->output = NULL;
    args->normal[1] = 1;
    args->seed = 1;
    args->settings = jensen1994_settings_default();
    args->settings.gather = PROBE_DEFAULT_GATHER;
    args->settings.n_photons = PROBE_DEFAULT_PHOTONS;
    struct option_once once = {{0}, 0};
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            printf("%s\n\nSamples the irradiance at N points along the line from (X0, Y0, Z0) to "
                   "(X1, Y1, Z1)\non a surface of the given normal, and writes one CSV row per "
                   "point: x,y,z,\nexact_direct,exact_caustic (point lights and flat mirrors "
                   "only; none otherwise),\ncaustic_photons, caustic_photons_unchecked, "
                   "all_photons (mode 1994's estimates\nfrom --gather photons, default %d), "
                   "caustic_illumination (its illumination map).\n--photons: light rays, "
                   "default %d.\n", PROBE_USAGE_NAMES "\n                    " PROBE_USAGE_OPTIONS,
                   PROBE_DEFAULT_GATHER, PROBE_DEFAULT_PHOTONS);
            return 1;
        }
        if (argv[i][0] == '-' && argv[i][1] != '\0') {
            if (read_probe_option(argc, argv, &i, args, &once, err) < 0)
                return -1;
        } else if (args->scene_path == NULL) {
            args->scene_path = argv[i];
        } else {
            return error_set(err, "", 0, "probe: more than one scene; " PROBE_USAGE);
        }
    }
    double n2 = args->normal[0] * args->normal[0] + args->normal[1] * args->normal[1] +
                args->normal[2] * args->normal[2];
    int degenerate = args->line[0] == args->line[3] && args->line[1] == args->line[4] &&
                     args->line[2] == args->line[5];
    if (args->scene_path == NULL || args->output == NULL || args->samples == 0 || degenerate)
        return error_set(err, "", 0, "probe: SCENE, --line (two different points), --samples "
                                     "and -o are needed; " PROBE_USAGE);
    if (!(n2 > 0))
        return error_set(err, "", 0, "probe: --normal must not be zero");
    return 0;
}

/* Irradiance at p (unit normal n) straight from the point lights, shadow-tested; NaN when
 * the scene has an area light, whose exact irradiance this does not compute. */
static double direct_irradiance(const struct scene *scene, struct vec3 p, struct vec3 n)
{
    double e = 0;
    for (size_t i = 0; i < scene->n_lights; i++) {
        const struct light *l = &scene->lights[i];
        struct light_sample ls;
        if (l->kind != LIGHT_POINT)
            return NAN;
        double cos_theta = light_sample(l, p, n, 0.5, 0.5, &ls) ? vec3_dot(n, ls.wi) : 0;
        if (cos_theta > 0 && !scene_occluded(scene, offset_origin(p, n), ls.wi, ls.distance))
            e += vec3_luminance(ls.li) * cos_theta / ls.pdf; /* pdf 1: a delta */
    }
    return e;
}

/* The irradiance at p from point light l reflected once by the planar mirror primitive
 * prim: the light's image source l' behind the mirror's plane shines on p through the
 * mirror's outline (Fig. 7), E = rho I cos / |p - l'|^2, I = Phi / (4 pi), when the ray
 * from p towards l' meets the mirror first and the mirror point sees the light. */
static double image_source_irradiance(const struct scene *scene, const struct light *l,
                                      int prim, struct vec3 p, struct vec3 n)
{
    struct vec3 q, m;
    if (!geometry_primitive_plane(scene->geometry, prim, &q, &m))
        return 0;
    double light_side = vec3_dot(vec3_sub(l->position, q), m);
    if (!(light_side * vec3_dot(vec3_sub(p, q), m) > 0))
        return 0; /* the light and p on different sides: no reflection joins them */
    struct vec3 image = vec3_sub(l->position, vec3_scale(m, 2 * light_side));
    struct vec3 to_image = vec3_sub(image, p);
    double d = vec3_length(to_image);
    struct vec3 wi = vec3_scale(to_image, 1.0 / d);
    double cos_theta = vec3_dot(n, wi);
    struct hit hit;
    if (!(cos_theta > 0) || !scene_intersect(scene, make_ray(offset_origin(p, n), wi), d, &hit) ||
        hit.prim != prim || scene->materials[hit.material].kind != MATERIAL_MIRROR)
        return 0;
    struct vec3 to_light = vec3_sub(l->position, hit.p);
    double distance = vec3_length(to_light);
    struct vec3 side = light_side > 0 ? m : vec3_neg(m);
    if (scene_occluded(scene, offset_origin(hit.p, side), vec3_scale(to_light, 1.0 / distance),
                       distance))
        return 0;
    double intensity = vec3_luminance(vec3_mul(scene->materials[hit.material].rho,
                                               light_power(l))) / (4 * PI);
    return intensity * cos_theta / (d * d);
}

/* Irradiance at p from one ideal reflection of each point light off every planar mirror;
 * NaN when the scene has an area light. */
static double caustic_irradiance(const struct scene *scene, struct vec3 p, struct vec3 n)
{
    double e = 0;
    size_t n_prims = geometry_primitive_count(scene->geometry);
    for (size_t i = 0; i < scene->n_lights; i++) {
        if (scene->lights[i].kind != LIGHT_POINT)
            return NAN;
        for (size_t prim = 0; prim < n_prims; prim++)
            e += image_source_irradiance(scene, &scene->lights[i], (int)prim, p, n);
    }
    return e;
}

/* A CSV field: the number, or CSV_NONE for NaN (no value here), which plot reads as a
 * point to leave out. */
static void write_field(FILE *f, double value)
{
    if (isnan(value))
        fputs("," CSV_NONE, f);
    else
        fprintf(f, ",%.9g", value);
}

/* The two stores the profile reads: photon maps everywhere, and illumination maps on the
 * surfaces that have them (the same light rays: the same seed). */
struct probe_stores {
    struct irradiance_stores photons, illumination;
};

/* The caustic irradiance at p from the illumination map of the surface under p (found
 * by a ray from just above p along -n); NaN when p lies on no surface with a map. */
static double illumination_caustic(const struct scene *scene, const struct irradiance_stores *st,
                                   struct vec3 p, struct vec3 n)
{
    struct hit hit;
    double reach = 1e-6 * scene_diagonal(scene);
    struct vec3 above = vec3_add(p, vec3_scale(n, reach));
    if (!scene_intersect(scene, make_ray(above, vec3_neg(n)), 2 * reach, &hit) ||
        !illumination_covers(st->illumination, hit.prim))
        return NAN;
    return vec3_luminance(illumination_irradiance(st->illumination, hit.prim, hit.u, hit.v, 1));
}

/* The profile's rows into f. */
static void write_profile(FILE *f, const struct scene *scene, const struct probe_stores *st,
                          const struct probe_args *args, struct nearest *nn)
{
    struct vec3 a = vec3(args->line[0], args->line[1], args->line[2]);
    struct vec3 b = vec3(args->line[3], args->line[4], args->line[5]);
    struct vec3 n = vec3_normalize(vec3(args->normal[0], args->normal[1], args->normal[2]));
    double max_r = PHOTONS_RADIUS_FRACTION * scene_diagonal(scene);
    const struct jensen1994_settings *settings = &args->settings;
    struct irradiance_settings checked = {settings->gather, max_r * max_r, PHOTON_CAUSTIC,
                                          settings->differential_run, settings->exclude_rim};
    struct irradiance_settings unchecked = checked, all = checked;
    unchecked.run = 0;
    all.kinds = 0;
    const struct kdtree *map = st->photons.photons;
    fputs("x,y,z,exact_direct,exact_caustic,caustic_photons,caustic_photons_unchecked,"
          "all_photons,caustic_illumination\n", f);
    for (int i = 0; i < args->samples; i++) {
        struct vec3 p = vec3_add(a, vec3_scale(vec3_sub(b, a), (double)i / (args->samples - 1)));
        fprintf(f, "%.9g,%.9g,%.9g", p.x, p.y, p.z);
        write_field(f, direct_irradiance(scene, p, n));
        write_field(f, caustic_irradiance(scene, p, n));
        write_field(f, vec3_luminance(irradiance_estimate(map, p, n, &checked, nn)));
        write_field(f, vec3_luminance(irradiance_estimate(map, p, n, &unchecked, nn)));
        write_field(f, vec3_luminance(irradiance_estimate(map, p, n, &all, nn)));
        write_field(f, illumination_caustic(scene, &st->illumination, p, n));
        fputc('\n', f);
    }
}

/* Writes the profile to args->output through a temporary file renamed when complete. */
static int write_probe(const struct scene *scene, const struct probe_stores *st,
                       const struct probe_args *args, struct error *err)
{
    FILE *f = output_open(args->output, err);
    if (f == NULL)
        return -1;
    struct nearest *nn = nearest_create(args->settings.gather);
    write_profile(f, scene, st, args, nn);
    nearest_free(nn);
    return output_commit(f, err); /* a failed write shows in ferror(), checked there */
}

int probe_command(int argc, char **argv)
{
    struct probe_args args;
    struct error err;
    int parsed = parse_probe_args(argc, argv, &args, &err);
    if (parsed != 0) {
        if (parsed < 0)
            error_print(&err);
        return parsed < 0 ? 2 : 0;
    }
    struct scene *scene = output_check_one(args.output, "-o", &err) == 0
                              ? scene_load(args.scene_path, &err)
                              : NULL;
    if (scene == NULL) {
        error_print(&err);
        return 2;
    }
    scene_finish(scene, scene->width, scene->height);
    struct jensen1994_stats stats;
    memset(&stats, 0, sizeof stats);
    struct probe_stores st;
    memset(&st, 0, sizeof st);
    struct jensen1994_settings with_maps = args.settings;
    with_maps.illumination_maps = 1;
    int status = jensen1994_trace(scene, args.seed, MAX_DEPTH_LIMIT, &args.settings, &st.photons,
                                  &stats, 0, &err) == 0 &&
                         jensen1994_trace(scene, args.seed, MAX_DEPTH_LIMIT, &with_maps,
                                          &st.illumination, &stats, 0, &err) == 0 &&
                         write_probe(scene, &st, &args, &err) == 0 &&
                         outputs_publish(&err) == 0
                     ? 0
                     : error_exit_status(&err);
    if (status != 0)
        error_print(&err);
    irradiance_stores_free(&st.photons);
    irradiance_stores_free(&st.illumination);
    scene_free(scene);
    return status;
}
