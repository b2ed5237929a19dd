/*
 * reference/ppm-fig4.c -- the data of reference/ppm-fig4.png, the 2008 paper's Fig. 4 on
 * the Cornell box: R(x) and N(x) of three hit points, pass after pass (Eq. 7 and 9 at
 * work), with photons the only light and R0 one footprint. Not part of the renderer:
 * built and run by the commands in reference/README.md.
 *
 * Each hit point is the one eye ray 0 makes for its pixel, rendered as a crop of that one
 * pixel with that one eye ray, which gives it exactly the radius and photons it has in
 * the whole image: a hit point's R and N depend on its own place and the photons alone
 * (a crop is bit-identical to the same window of the whole render). For each of A, B, C it
 * writes DIR/R/NAME.csv and DIR/N/NAME.csv with the header photon plot reads,
 * "seconds,relmse", holding the pass and R(x) in mm, or the pass and N(x), at about
 * 2^(k/2) passes.
 */
#include <stdio.h>
#include <stdlib.h>

#include "../src/modes/ppm2008.h"
#include "../src/photon/hit_points.h"
#include "../src/scene/scene.h"

#define FIG4_PASSES 1024

struct tracked_point {
    const char *name; /* A, B or C                  */
    int x, y;         /* its pixel in the 256 x 256 box */
    const char *what; /* where it lies                */
};

static const struct tracked_point points[3] = {
    {"A", 40, 235, "floor, in the light"},
    {"B", 200, 20, "ceiling, lit only indirectly"},
    {"C", 180, 228, "floor, in the shadow of the nearer ball"},
};

struct track {
    FILE *r, *n; /* the two CSV files */
    long next;   /* the next pass written */
};

/* After each pass: R and N of hit point 0 of the crop, about every factor sqrt(2) in passes
 * and after the last. */
static void after_pass(void *context, long pass, const struct hit_point *hp, size_t n_points)
{
    struct track *t = context;
    if (n_points == 0 || (pass < t->next && pass != FIG4_PASSES))
        return;
    fprintf(t->r, "%ld,%.9g\n", pass, hp[0].global.radius);
    fprintf(t->n, "%ld,%.9g\n", pass, hp[0].global.n_photons);
    long step = (long)(t->next * 0.41421356); /* sqrt(2) - 1 */
    t->next += step > 0 ? step : 1;
}

static FILE *open_csv(const char *dir, const char *quantity, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s/%s.csv", dir, quantity, name);
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        perror(path);
        exit(1);
    }
    fprintf(f, "seconds,relmse\n");
    return f;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: ppm-fig4 DIR (DIR/R and DIR/N must exist)\n");
        return 2;
    }
    struct error err;
    struct scene *scene = scene_load("scenes/cornell.scene", &err);
    if (scene == NULL) {
        error_print(&err);
        return 2;
    }
    scene_finish(scene, 256, 256);
    for (int k = 0; k < 3; k++) {
        const struct tracked_point *p = &points[k];
        struct track t = {open_csv(argv[1], "R", p->name), open_csv(argv[1], "N", p->name), 1};
        struct ppm_observer observer = {after_pass, &t};
        struct render_settings rs = render_settings_whole(scene, 1, 1, MAX_DEPTH_LIMIT);
        rs.x0 = p->x;
        rs.y0 = p->y;
        rs.x1 = p->x + 1;
        rs.y1 = p->y + 1;
        struct ppm_settings ps = ppm_settings_default();
        ps.progressive.passes = FIG4_PASSES;
        ps.progressive.direct_light_samples = 0; /* every photon counts, as in the paper's Fig. 4 */
        ps.progressive.footprints = 1; /* R0 one footprint (shortened by walls), one estimate */
        ps.caustic_footprints = 0;
        ps.observer = &observer;
        struct render_counters counters = {0};
        struct ppm_stats stats;
        struct render_result result = render_ppm(scene, &rs, &ps, &counters, &stats);
        printf("%s: pixel (%d, %d), %s; %zu hit points; L = %.6g %.6g %.6g\n", p->name, p->x,
               p->y, p->what, stats.hit_points, result.image->pixels[0].x,
               result.image->pixels[0].y, result.image->pixels[0].z);
        render_result_free(&result);
        fclose(t.r);
        fclose(t.n);
    }
    scene_free(scene);
    return 0;
}
