/*
 * modes/ppm_error.c -- 2008's pass values for its error image (ppm_error.h); the bound
 * itself is 2009's (sppm_error.c).
 */
#include "ppm_error.h"

#include <string.h>
#include <time.h>

#include "../base/alloc.h"

/* What kept pixel i has seen so far: its emission seen and its direct term's sum. */
static struct vec3 seen_so_far(const struct vec3 *emission_seen,
                               const struct ppm_direct *direct, size_t i)
{
    return direct != NULL ? vec3_add(emission_seen[i], direct->sum[i]) : emission_seen[i];
}

void ppm_error_create(struct ppm_error *e, const struct kept_window *kept, size_t n_points,
                      const struct vec3 *emission_seen, const struct ppm_direct *direct)
{
    size_t n = (size_t)kept->width * (size_t)kept->height;
    e->kept = kept;
    sppm_error_create(&e->values, kept, BLOCK_BIAS_REACH);
    for (size_t i = 0; i < n; i++)
        e->values.before[i] = seen_so_far(emission_seen, direct, i);
    e->inner = xcalloc(2 * n_points + 1, sizeof *e->inner, "ppm inner flux");
    e->tau_before = xcalloc(2 * n_points + 1, sizeof *e->tau_before, "ppm flux");
    e->y = xmalloc(n, sizeof *e->y, "ppm pass values");
    e->y_inner = xmalloc(n, sizeof *e->y_inner, "ppm pass values");
    e->passes = 0;
}

void ppm_error_add_pass(struct ppm_error *e, const struct hit_point_tree *tree,
                        double photons_per_pass, const struct vec3 *emission_seen,
                        const struct ppm_direct *direct)
{
    size_t n = (size_t)e->values.width * (size_t)e->values.height;
    for (size_t i = 0; i < n; i++) { /* the photon parts, summed over the pixel's points */
        e->y[i] = vec3_zero();
        e->y_inner[i] = vec3_zero();
    }
    for (size_t k = 0; k < tree->n; k++) { /* the k-th made: w (P_i + C_i) */
        size_t j = tree->place[k];
        const struct hit_point *hp = &tree->points[j];
        const struct progressive_estimate *estimate[2] = {&hp->global, &hp->caustic};
        for (size_t c = 0; c < 2; c++) { /* tau_M: what the pass added to tau */
            struct vec3 p, p_inner, taken = vec3_sub(estimate[c]->tau, e->tau_before[2 * j + c]);
            sppm_error_photons(hp->weight, estimate[c]->radius, taken, e->inner[2 * j + c],
                               photons_per_pass, &p, &p_inner);
            e->y[hp->pixel] = vec3_add(e->y[hp->pixel], p);
            e->y_inner[hp->pixel] = vec3_add(e->y_inner[hp->pixel], p_inner);
        }
    }
    memset(e->inner, 0, 2 * tree->n * sizeof *e->inner);
    for (size_t i = 0; i < n; i++) { /* e_i + d_i: what the pass's eye ray saw and took */
        struct vec3 now = seen_so_far(emission_seen, direct, i);
        sppm_error_add_pass(&e->values, i, vec3_sub(now, e->values.before[i]),
                            e->y[i], e->y_inner[i]);
        e->values.before[i] = now;
    }
    sppm_error_pass_done(&e->values, e->passes);
    e->passes++;
}

void ppm_error_end_pass(struct ppm_error *e, const struct hit_point_tree *tree)
{
    for (size_t j = 0; j < tree->n; j++) {
        e->tau_before[2 * j] = tree->points[j].global.tau;
        e->tau_before[2 * j + 1] = tree->points[j].caustic.tau;
    }
}

int ppm_error_target(const struct ppm_error *e, const struct image *mean,
                     struct render_counters *counters)
{
    return sppm_error_target(&e->values, e->kept, e->passes, mean, counters);
}

double ppm_error_finish(struct ppm_error *e, struct render_result *result)
{
    clock_t start = clock();
    sppm_error_result(&e->values, e->kept, e->passes, result);
    sppm_error_free(&e->values);
    xfree(e->inner);
    xfree(e->tau_before);
    xfree(e->y);
    xfree(e->y_inner);
    memset(e, 0, sizeof *e);
    return cpu_seconds(start);
}
