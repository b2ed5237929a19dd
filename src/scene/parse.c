/*
 * scene/parse.c -- the scene file reader: one keyword per line (README, "Scene files").
 *
 * A file is read line by line; '#' starts a comment anywhere a token may start; tokens are
 * separated by any white space. Each keyword has one function that takes its numbers and
 * names, checks them (finite, in range, names defined) and adds to the scene: here the
 * file-level ones (image, camera, background, include), in parse_material.c the
 * materials, in parse_objects.c objects, lights and imports. Any problem
 * fills *err with the file, the line and what was expected, and parsing stops: the
 * caller frees the partial scene (scene_load), and nothing has been written anywhere.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../base/alloc.h"
#include "../base/input.h"
#include "../base/number.h"
#include "../image/image.h"
#include "nff.h"
#include "parser.h"
#include "reach.h"

static int parse_file(struct scene *scene, const char *path, int depth, struct error *err);

/* Fills *err with "file:line: keyword: message" and returns -1. */
int parse_error(const struct parser *ps, struct error *err, const char *message)
{
    return error_set(err, ps->file, ps->line, "%s: %s", ps->tokens[0], message);
}

const char *read_word(struct parser *ps)
{
    return ps->next < ps->n_tokens ? ps->tokens[ps->next++] : NULL;
}

/* Reads n numbers in base/number.h's syntax, whole ones when integer != 0; `what` names
 * them for the message ("centre x y z, radius"). */
static int read_numbers_of(struct parser *ps, double *v, int n, int integer, const char *what,
                           struct error *err)
{
    for (int i = 0; i < n; i++) {
        const char *word = read_word(ps);
        if (word == NULL)
            return error_set(err, ps->file, ps->line, "%s: expected %d %s (%s), got %d",
                             ps->tokens[0], n, integer ? "whole numbers" : "numbers", what, i);
        enum number_verdict verdict = number_read(word, integer, &v[i]);
        if (verdict == NUMBER_UNWRITTEN)
            return error_set(err, ps->file, ps->line, "%s: '%s' %s (expected %s)",
                             ps->tokens[0], word, number_problem(verdict, integer), what);
        if (verdict != NUMBER_OK)
            return error_set(err, ps->file, ps->line, "%s: number '%s' %s", ps->tokens[0],
                             word, number_problem(verdict, integer));
    }
    return 0;
}

int read_numbers(struct parser *ps, double *v, int n, const char *what, struct error *err)
{
    return read_numbers_of(ps, v, n, 0, what, err);
}

int read_wholes(struct parser *ps, double *v, int n, const char *what, struct error *err)
{
    return read_numbers_of(ps, v, n, 1, what, err);
}

/* Whether the next word is written as a number (an optional parameter follows): one that
 * is out of range is read, and refused, as a number, not taken for a name. */
int next_is_number(const struct parser *ps)
{
    return ps->next < ps->n_tokens && number_in_syntax(ps->tokens[ps->next], 0);
}

int expect_end(struct parser *ps, struct error *err)
{
    const char *extra = read_word(ps);
    if (extra == NULL)
        return 0;
    return error_set(err, ps->file, ps->line, "%s: unexpected '%s' at the end of the line",
                     ps->tokens[0], extra);
}

/* Reads a material name that must already be defined; returns its index or -1. */
int read_material(struct parser *ps, struct error *err)
{
    const char *name = read_word(ps);
    if (name == NULL)
        return parse_error(ps, err, "expected a material name at the end");
    int m = scene_find_material(ps->scene, name);
    if (m < 0)
        return error_set(err, ps->file, ps->line, "%s: undefined material '%s'",
                         ps->tokens[0], name);
    return m;
}

int is_colour_in(const double *v, double lo, double hi)
{
    for (int i = 0; i < 3; i++)
        if (!(v[i] >= lo && v[i] <= hi))
            return 0;
    return 1;
}

/* "image WIDTH HEIGHT" */
static int parse_image(struct parser *ps, struct error *err)
{
    double v[2];
    if (read_wholes(ps, v, 2, "width, height: whole numbers of pixels", err) < 0)
        return -1;
    for (int i = 0; i < 2; i++)
        if (!(v[i] >= 1 && v[i] <= MAX_IMAGE_SIDE))
            return error_set(err, ps->file, ps->line,
                             "image: size must be whole numbers from 1 to %d, got %s",
                             MAX_IMAGE_SIDE, ps->tokens[1 + i]); /* as typed */
    ps->scene->width = (int)v[0];
    ps->scene->height = (int)v[1];
    return expect_end(ps, err);
}

/* The optional end of a camera line, "aperture RADIUS focus DISTANCE": a thin lens. */
static int parse_lens(struct parser *ps, struct camera *c, struct error *err)
{
    double v[1];
    const char *word = read_word(ps);
    if (word == NULL)
        return 0;
    if (strcmp(word, "aperture") != 0)
        return error_set(err, ps->file, ps->line, "camera: unexpected '%s' after the field "
                         "of view (expected 'aperture RADIUS focus DISTANCE')", word);
    if (read_numbers(ps, v, 1, "the lens's radius", err) < 0)
        return -1;
    if (!(v[0] >= 0))
        return parse_error(ps, err, "aperture: the lens's radius must be at least 0");
    c->lens_radius = v[0];
    word = read_word(ps);
    if (word == NULL || strcmp(word, "focus") != 0)
        return parse_error(ps, err, "expected 'focus DISTANCE' after the aperture");
    if (read_numbers(ps, v, 1, "the distance in focus", err) < 0)
        return -1;
    if (!(v[0] > 0))
        return parse_error(ps, err, "focus: the distance in focus must be above 0");
    c->focus = v[0];
    return 0;
}

/* "camera FROM_X FROM_Y FROM_Z  AT_X AT_Y AT_Z  UP_X UP_Y UP_Z  FOV_DEGREES
 *  [aperture RADIUS focus DISTANCE]" */
static int parse_camera(struct parser *ps, struct error *err)
{
    double v[10];
    if (read_numbers(ps, v, 10, "position x y z, look-at x y z, up x y z, vertical fov", err))
        return -1;
    struct camera *c = &ps->scene->camera;
    c->from = vec3_at(v);
    c->at = vec3_at(v + 3);
    c->up = vec3_at(v + 6);
    c->fov = v[9];
    c->lens_radius = 0;
    c->focus = 1;
    if (parse_lens(ps, c, err) < 0)
        return -1;
    if (!(c->fov > 0 && c->fov < 180))
        return parse_error(ps, err, "vertical field of view must be in (0, 180) degrees");
    if (!camera_is_valid(c))
        return parse_error(ps, err, "look-at point equals the position, or up is parallel "
                                    "to the viewing direction");
    ps->scene->has_camera = 1;
    ps->scene->reach.camera_counted = 0; /* a later camera line replaces this one: count it */
    return expect_end(ps, err);
}

/* "background R G B": radiance of rays that leave the scene */
static int parse_background(struct parser *ps, struct error *err)
{
    double v[3];
    if (read_numbers(ps, v, 3, "radiance r g b", err) < 0)
        return -1;
    if (!is_colour_in(v, 0, HUGE_VAL))
        return parse_error(ps, err, "radiance must not be negative");
    scene_set_background(ps->scene, vec3_at(v), ps->file, ps->line);
    return expect_end(ps, err);
}

/* Reports a failed scene_add_*(): the only causes are documented limits. */
int check_added(struct parser *ps, int id, struct error *err)
{
    return scene_add_error(id, ps->file, ps->line, ps->tokens[0], err);
}

/* Reads a file name into path[MAX_PATH_LENGTH], relative to the directory of the file
 * being read unless it starts with '/'. */
int read_path(struct parser *ps, char *path, struct error *err)
{
    const char *name = read_word(ps);
    if (name == NULL)
        return parse_error(ps, err, "expected a file name");
    const char *slash = strrchr(ps->file, '/');
    int dir_length = (name[0] == '/' || slash == NULL) ? 0 : (int)(slash - ps->file + 1);
    if (dir_length + strlen(name) + 1 > MAX_PATH_LENGTH)
        return parse_error(ps, err, "path is too long");
    sprintf(path, "%.*s%s", dir_length, ps->file, name);
    return 0;
}

int check_named_file(struct parser *ps, const char *path, struct error *err)
{
    struct input in;
    struct error inner;
    int status = input_open(&in, path, &inner);
    input_close(&in);
    if (status == 0)
        return 0;
    const char *reason = inner.message;
    if (strncmp(reason, "cannot open: ", 13) == 0)
        reason += 13;
    return error_set(err, ps->file, ps->line, "%s: cannot open '%s': %s", ps->tokens[0], path,
                     reason);
}

/* "include FILE": FILE is relative to the directory of the including file. */
static int parse_include(struct parser *ps, struct error *err)
{
    char path[MAX_PATH_LENGTH];
    if (read_path(ps, path, err) < 0 || expect_end(ps, err) < 0 ||
        check_named_file(ps, path, err) < 0)
        return -1;
    if (ps->depth + 1 > MAX_INCLUDE_DEPTH)
        return error_set(err, ps->file, ps->line,
                         "include: nested more than %d deep (an include cycle?)",
                         MAX_INCLUDE_DEPTH);
    return parse_file(ps->scene, path, ps->depth + 1, err);
}

struct keyword {
    const char *name;
    int (*parse)(struct parser *ps, struct error *err);
};

static const struct keyword keywords[] = {
    {"image", parse_image},       {"camera", parse_camera},
    {"background", parse_background}, {"material", parse_material},
    {"sphere", parse_sphere},     {"triangle", parse_triangle},
    {"smooth_triangle", parse_triangle}, {"quad", parse_quad},
    {"light", parse_light},       {"include", parse_include},
    {"sphereflake", parse_sphereflake}, {"heightfield", parse_heightfield},
    {"nff", parse_nff},           {"obj", parse_obj},
};

/* Cuts ps->text into tokens at white space, stopping at a '#' that starts a token. */
static int split_tokens(struct parser *ps, struct error *err)
{
    char *s = ps->text;
    ps->n_tokens = 0;
    ps->next = 1;
    for (;;) {
        while (isspace((unsigned char)*s))
            *s++ = '\0';
        if (*s == '\0' || *s == '#')
            return 0;
        if (ps->n_tokens == MAX_TOKENS)
            return error_set(err, ps->file, ps->line, "more than %d words on a line",
                             MAX_TOKENS);
        ps->tokens[ps->n_tokens++] = s;
        while (*s != '\0' && !isspace((unsigned char)*s))
            s++;
    }
}

static int parse_line(struct parser *ps, struct error *err)
{
    if (split_tokens(ps, err) < 0)
        return -1;
    if (ps->n_tokens == 0)
        return 0;
    for (size_t i = 0; i < sizeof keywords / sizeof keywords[0]; i++)
        if (strcmp(ps->tokens[0], keywords[i].name) == 0)
            return keywords[i].parse(ps, err);
    return error_set(err, ps->file, ps->line, "unknown keyword '%.40s'", ps->tokens[0]);
}

/* Reads every line of one file; stops at the first error. */
static int parse_lines(struct parser *ps, struct input *in, struct error *err)
{
    int status;
    while ((status = input_line(in, ps->text, sizeof ps->text, err)) > 0) {
        ps->line = in->line;
        scene_hash_line(ps->scene, ps->text);
        if (parse_line(ps, err) < 0)
            return -1;
        reach_note(ps->scene, ps->file, ps->line);
    }
    return status;
}

static int parse_file(struct scene *scene, const char *path, int depth, struct error *err)
{
    struct input in;
    if (input_open(&in, path, err) < 0)
        return -1;
    /* The parser is large (a line buffer), so it lives on the heap, not the stack. */
    struct parser *ps = xcalloc(1, sizeof *ps, "parser");
    ps->scene = scene;
    ps->file = path;
    ps->depth = depth;
    int status = parse_lines(ps, &in, err);
    xfree(ps);
    input_close(&in);
    return status;
}

/* The sky, once the last primitive is in (scene_add_sky()): its power limit is the
 * background line's error. */
static int add_sky(struct scene *scene, struct error *err)
{
    int light = scene_add_sky(scene);
    if (light == SCENE_TOO_BRIGHT)
        return error_set(err, scene->background_file, scene->background_line,
                         "background: the sky's power, radiance x pi R^2 x 4 pi for the "
                         "radius R of the sphere around the scene, would take the lights' "
                         "total past %g W in a channel", MAX_LIGHT_POWER);
    return scene_add_error(light == -1 ? 0 : light, scene->background_file,
                           scene->background_line, "background", err);
}

struct scene *scene_load(const char *path, struct error *err)
{
    size_t length = strlen(path);
    struct scene *scene;
    if (length > 4 && strcmp(path + length - 4, ".nff") == 0) {
        scene = nff_load(path, err);
        if (scene == NULL)
            return NULL;
    } else {
        scene = scene_create();
        if (parse_file(scene, path, 0, err) < 0) {
            scene_free(scene);
            return NULL;
        }
        if (!scene->has_camera) {
            error_set(err, path, 0, "no camera: a scene needs a 'camera' line");
            scene_free(scene);
            return NULL;
        }
    }
    if (add_sky(scene, err) < 0) {
        scene_free(scene);
        return NULL;
    }
    if (reach_check(scene, err) < 0) {
        scene_free(scene);
        return NULL;
    }
    return scene;
}
