/*
 * scene/reach.c -- the scene's reach against what double precision resolves (reach.h).
 */
#include "reach.h"

#include <stdio.h>

#include "scene.h"

/* Raises the reach to v, remembering file:line when it does. */
static void extend(struct scene_reach *r, double v, const char *file, int line)
{
    if (v > r->reach) {
        r->reach = v;
        snprintf(r->file, sizeof r->file, "%s", file);
        r->line = line;
    }
}

void reach_note(struct scene *scene, const char *file, int line)
{
    struct scene_reach *r = &scene->reach;
    for (; r->n_prims < geometry_primitive_count(scene->geometry); r->n_prims++) {
        struct aabb box = geometry_primitive_bounds(scene->geometry, (int)r->n_prims);
        extend(r, fmax(vec3_max_abs(box.lo), vec3_max_abs(box.hi)), file, line);
    }
    for (; r->n_lights < scene->n_lights; r->n_lights++)
        if (scene->lights[r->n_lights].kind == LIGHT_POINT)
            extend(r, vec3_max_abs(scene->lights[r->n_lights].position), file, line);
    if (scene->has_camera && !r->camera_counted) {
        r->camera_counted = 1;
        snprintf(r->camera_file, sizeof r->camera_file, "%s", file);
        r->camera_line = line;
        const struct camera *c = &scene->camera;
        extend(r, fmax(vec3_max_abs(c->from) + c->lens_radius, vec3_max_abs(c->at)), file, line);
        if (c->lens_radius > 0) /* the plane in focus, where every lens ray aims */
            extend(r, vec3_max_abs(c->from) + c->focus, file, line);
    }
}

int reach_check(const struct scene *scene, struct error *err)
{
    const struct scene_reach *r = &scene->reach;
    double distance = vec3_length(vec3_sub(scene->camera.at, scene->camera.from));
    if (!(distance >= REACH_MIN_CAMERA))
        return error_set(err, r->camera_file, r->camera_line, "camera: %g from its look-at "
                         "point, below %g: rays leave a surface 1e-9 x max(1, |p|) off it, "
                         "so a scene this small loses its shadows (scale it up; README: "
                         "Scene files)", distance, REACH_MIN_CAMERA);
    if (r->reach > REACH_MAX_RATIO * distance)
        return error_set(err, r->file, r->line, "reaches %g from the origin, more than 2^40 "
                         "times the camera's distance to its look-at point (%g): double "
                         "precision cannot resolve the scene there (README: Scene files)",
                         r->reach, distance);
    return 0;
}
