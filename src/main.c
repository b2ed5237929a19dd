/*
 * main.c -- photon's command line: options -> scene -> mode -> outputs.
 *
 * Exit status: 0 on success, 2 for bad input (options, scene files, image files; the
 * message names file:line), 1 for a machine failure (out of memory, a failed write).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/options.h"
#include "image/compare.h"
#include "modes/direct.h"

static double seconds_since(clock_t start)
{
    return (double)(clock() - start) / CLOCKS_PER_SEC;
}

/* The render window: the crop if one was given (checked against the image), else all. */
static int choose_window(const struct options *o, int width, int height,
                         struct render_settings *rs, struct error *err)
{
    rs->x0 = 0;
    rs->y0 = 0;
    rs->x1 = width;
    rs->y1 = height;
    if (o->crop[2] == 0)
        return 0;
    if (!(o->crop[0] < o->crop[2] && o->crop[2] <= width && o->crop[1] < o->crop[3] &&
          o->crop[3] <= height))
        return error_set(err, "", 0,
                         "--crop %d %d %d %d: need X0 < X1 <= %d and Y0 < Y1 <= %d (the image)",
                         o->crop[0], o->crop[1], o->crop[2], o->crop[3], width, height);
    rs->x0 = o->crop[0];
    rs->y0 = o->crop[1];
    rs->x1 = o->crop[2];
    rs->y1 = o->crop[3];
    return 0;
}

/* Progress is shown when asked for, or by default when the environment looks like an
 * interactive terminal: C99 cannot ask whether stderr is one, so TERM stands in for it. */
static int show_progress(int requested)
{
    if (requested >= 0)
        return requested;
    const char *term = getenv("TERM");
    return term != NULL && strcmp(term, "dumb") != 0 && getenv("CI") == NULL;
}

static int write_outputs(const struct options *o, const struct image *img, struct error *err)
{
    char ppm[OUTPUT_PATH_MAX];
    strcpy(ppm, o->output);
    strcpy(ppm + strlen(ppm) - 4, ".ppm"); /* the name ends in .pfm (parse_options) */
    if (pfm_write(o->output, img, err) < 0 || ppm_write(ppm, img, o->exposure, err) < 0)
        return -1;
    return 0;
}

static void print_stats(const struct options *o, const struct scene *scene,
                        const struct render_counters *c, double seconds_build,
                        double seconds_total)
{
    fprintf(stderr, "mode=%s\nseconds_total=%.3f\nseconds_build=%.3f\n", mode_name(o->mode),
            seconds_total, seconds_build);
    fprintf(stderr, "rays=%llu\nnonfinite_samples=%llu\n", c->rays, c->nonfinite_samples);
    fprintf(stderr, "objects=%zu\nlights=%zu\nbvh_nodes=%zu\nbytes_geometry=%zu\n",
            geometry_primitive_count(scene->geometry), scene->n_lights,
            geometry_bvh_nodes(scene->geometry), geometry_bytes(scene->geometry));
    fprintf(stderr, "width=%d\nheight=%d\nspp=%d\nseed=%llu\n", scene->width, scene->height,
            o->spp, (unsigned long long)o->seed);
}

static int render_command(const struct options *o, struct error *err)
{
    clock_t start = clock();
    struct scene *scene = scene_load(o->scene_path, err);
    if (scene == NULL)
        return 2;
    int width = o->width > 0 ? o->width : scene->width;
    int height = o->height > 0 ? o->height : scene->height;
    struct render_settings rs;
    rs.seed = o->seed;
    rs.spp = o->spp;
    rs.max_depth = o->max_depth;
    rs.progress = show_progress(o->progress);
    if (choose_window(o, width, height, &rs, err) < 0) {
        scene_free(scene);
        return 2;
    }
    scene_finish(scene, width, height);
    double seconds_build = seconds_since(start);
    struct render_counters counters = {0, 0};
    struct image *img = render_direct(scene, &rs, &counters);
    int status = write_outputs(o, img, err) < 0 ? 2 : 0;
    if (status == 0 && o->stats)
        print_stats(o, scene, &counters, seconds_build, seconds_since(start));
    image_free(img);
    scene_free(scene);
    return status;
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "compare") == 0)
        return compare_command(argc - 1, argv + 1);
    struct options o;
    struct error err;
    int parsed = parse_options(argc, argv, &o, &err);
    if (parsed != 0) {
        if (parsed < 0)
            error_print(&err);
        return parsed < 0 ? 2 : 0;
    }
    int status = render_command(&o, &err);
    if (status != 0)
        error_print(&err);
    return status;
}
