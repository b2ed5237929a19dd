/*
 * scene/parser.h -- the parts of the scene-file reader that its keyword files share.
 *
 * Not a public interface (that is scene_load() in scene.h): parse.c reads files, lines
 * and words and dispatches each keyword; parse_material.c reads materials;
 * parse_objects.c reads objects, lights and imports. A keyword function reads the rest
 * of its line from the parser, adds to ps->scene, and returns 0, or -1 with *err filled
 * with the file, the line and what was expected.
 */
#ifndef PHOTON_PARSER_H
#define PHOTON_PARSER_H

#include "scene.h"

#define MAX_LINE 4096         /* longest line, in bytes, including the newline          */
#define MAX_TOKENS 64         /* the longest keyword line (smooth_triangle) has 20      */
#define MAX_INCLUDE_DEPTH 16  /* include nesting; deeper is taken for an include cycle  */
#define MAX_PATH_LENGTH 1024  /* longest path an include may produce                    */

struct parser {
    struct scene *scene;
    const char *file;          /* the file being read, as named                */
    int line;                  /* 1-based line number in file                  */
    int depth;                 /* include depth of this file, 0 at the top     */
    char text[MAX_LINE];       /* the current line, cut into tokens in place   */
    char *tokens[MAX_TOKENS];  /* the current line's tokens                    */
    int n_tokens;
    int next;                  /* index of the next token to be read           */
};

/* Fills *err with "file:line: keyword: message" and returns -1. */
int parse_error(const struct parser *ps, struct error *err, const char *message);
/* The next word of the line, or NULL at its end. */
const char *read_word(struct parser *ps);
/* Reads n numbers (base/number.h's syntax) into v; `what` names them for the message. */
int read_numbers(struct parser *ps, double *v, int n, const char *what, struct error *err);
/* Reads n whole numbers ("8", not "8.0", "8e0" or "0x8") into v, like read_numbers(). */
int read_wholes(struct parser *ps, double *v, int n, const char *what, struct error *err);
/* Whether the next word is a number (an optional parameter follows). */
int next_is_number(const struct parser *ps);
/* -1 with a message if anything is left on the line. */
int expect_end(struct parser *ps, struct error *err);
/* Reads the name of a defined material; returns its index or -1. */
int read_material(struct parser *ps, struct error *err);
/* Whether each of the three values is in [lo, hi]. */
int is_colour_in(const double *v, double lo, double hi);
/* Reports a failed scene_add_*() (id < 0): a documented limit was reached. */
int check_added(struct parser *ps, int id, struct error *err);
/* Reads a file name into path[MAX_PATH_LENGTH], relative to the directory of the file
 * being read unless it starts with '/'. */
int read_path(struct parser *ps, char *path, struct error *err);
/* Whether the file at path, which this line names (include, obj, nff), opens as an input
 * (base/input.h: a regular file, not an output of the command); -1
 * with *err naming this file and line otherwise ("x.scene:3: obj: cannot open 'mesh.obj':
 * No such file or directory"), so that a missing file is reported where it is named. */
int check_named_file(struct parser *ps, const char *path, struct error *err);

static inline struct vec3 vec3_at(const double *v) { return vec3(v[0], v[1], v[2]); }

/* Keywords (parse_material.c, parse_objects.c). */
int parse_material(struct parser *ps, struct error *err);
int parse_sphere(struct parser *ps, struct error *err);
int parse_triangle(struct parser *ps, struct error *err);
int parse_quad(struct parser *ps, struct error *err);
int parse_light(struct parser *ps, struct error *err);
int parse_sphereflake(struct parser *ps, struct error *err);
int parse_heightfield(struct parser *ps, struct error *err);
int parse_nff(struct parser *ps, struct error *err);
int parse_obj(struct parser *ps, struct error *err);

#endif
