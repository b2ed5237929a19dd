/*
 * scene/parse_material.c -- the `material` keyword of scene files (README: Scene files):
 * a name, a reflection model with its parameters, and optional emission. Every value is
 * checked against the model's range, so scene/brdf.c can assert instead of check.
 */
#include <string.h>

#include "parser.h"

/* Reads an RGB reflectance, each channel in [0, 1]. */
static int read_reflectance(struct parser *ps, struct vec3 *rho, const char *what,
                            struct error *err)
{
    double v[3];
    if (read_numbers(ps, v, 3, what, err) < 0)
        return -1;
    if (!is_colour_in(v, 0, 1))
        return error_set(err, ps->file, ps->line, "%s: %s must be in [0, 1] per channel",
                         ps->tokens[0], what);
    *rho = vec3_at(v);
    return 0;
}

/* Whether a + b <= 1 in every channel: the energy bound of a two-lobe model. */
static int sums_to_at_most_one(struct vec3 a, struct vec3 b)
{
    return a.x + b.x <= 1 && a.y + b.y <= 1 && a.z + b.z <= 1;
}

/* "phong KD_R KD_G KD_B KS_R KS_G KS_B EXPONENT" */
static int parse_phong(struct parser *ps, struct material *m, struct error *err)
{
    if (read_reflectance(ps, &m->rho, "diffuse kd r g b", err) < 0 ||
        read_reflectance(ps, &m->rho_s, "specular ks r g b", err) < 0 ||
        read_numbers(ps, &m->exponent, 1, "exponent", err) < 0)
        return -1;
    if (!sums_to_at_most_one(m->rho, m->rho_s))
        return parse_error(ps, err, "phong: kd + ks must not exceed 1 in any channel");
    if (!(m->exponent >= 0))
        return parse_error(ps, err, "phong: the exponent must not be negative");
    return 0;
}

/* "ward RD_R RD_G RD_B RS_R RS_G RS_B ALPHA_X ALPHA_Y" */
static int parse_ward(struct parser *ps, struct material *m, struct error *err)
{
    double alpha[2];
    if (read_reflectance(ps, &m->rho, "diffuse rho_d r g b", err) < 0 ||
        read_reflectance(ps, &m->rho_s, "specular rho_s r g b", err) < 0 ||
        read_numbers(ps, alpha, 2, "alpha_x, alpha_y", err) < 0)
        return -1;
    if (!sums_to_at_most_one(m->rho, m->rho_s))
        return parse_error(ps, err, "ward: rho_d + rho_s must not exceed 1 in any channel");
    if (!(alpha[0] > 0 && alpha[1] > 0))
        return parse_error(ps, err, "ward: alpha_x and alpha_y must be positive");
    m->alpha_x = alpha[0];
    m->alpha_y = alpha[1];
    return 0;
}

/* "schlick C_R C_G C_B ROUGHNESS [ISOTROPY]" */
static int parse_schlick(struct parser *ps, struct material *m, struct error *err)
{
    if (read_reflectance(ps, &m->rho, "colour r g b", err) < 0 ||
        read_numbers(ps, &m->roughness, 1, "roughness", err) < 0)
        return -1;
    if (!(m->roughness >= 0 && m->roughness <= 1))
        return parse_error(ps, err, "schlick: roughness must be in [0, 1]");
    m->isotropy = 1.0; /* isotropic unless a number follows */
    if (next_is_number(ps) && read_numbers(ps, &m->isotropy, 1, "isotropy", err) < 0)
        return -1;
    if (!(m->isotropy > 0 && m->isotropy <= 1))
        return parse_error(ps, err, "schlick: isotropy must be in (0, 1]");
    return 0;
}

/* "glass IOR [T_R T_G T_B]": T is the colour a refraction lets through (clear: 1 1 1). */
static int parse_glass(struct parser *ps, struct material *m, struct error *err)
{
    m->kind = MATERIAL_GLASS;
    if (read_numbers(ps, &m->ior, 1, "index of refraction", err) < 0)
        return -1;
    if (!(m->ior > 0))
        return parse_error(ps, err, "index of refraction must be positive");
    struct vec3 filter = vec3(1.0, 1.0, 1.0);
    if (next_is_number(ps) && read_reflectance(ps, &filter, "filter colour r g b", err) < 0)
        return -1;
    m->absorption = vec3_sub(vec3(1.0, 1.0, 1.0), filter);
    return 0;
}

/* The reflection part of "material NAME KIND ...". */
static int parse_material_kind(struct parser *ps, struct material *m, struct error *err)
{
    const char *kind = read_word(ps);
    if (kind == NULL)
        return parse_error(ps, err, "expected a kind after the name: lambert, mirror, glass, "
                                    "phong, ward or schlick");
    if (strcmp(kind, "lambert") == 0 || strcmp(kind, "mirror") == 0) {
        m->kind = kind[0] == 'l' ? MATERIAL_LAMBERT : MATERIAL_MIRROR;
        return read_reflectance(ps, &m->rho, "reflectance r g b", err);
    }
    if (strcmp(kind, "glass") == 0)
        return parse_glass(ps, m, err);
    static const struct {
        const char *name;
        enum material_kind kind;
        int (*parse)(struct parser *ps, struct material *m, struct error *err);
    } models[] = {{"phong", MATERIAL_PHONG, parse_phong},
                  {"ward", MATERIAL_WARD, parse_ward},
                  {"schlick", MATERIAL_SCHLICK, parse_schlick}};
    for (size_t i = 0; i < sizeof models / sizeof models[0]; i++)
        if (strcmp(kind, models[i].name) == 0) {
            m->kind = models[i].kind;
            return models[i].parse(ps, m, err);
        }
    return error_set(err, ps->file, ps->line,
                     "material: unknown kind '%s' (expected lambert, mirror, glass, phong, "
                     "ward or schlick)", kind);
}

/* The optional end "emit R G B [twosided]" of a material line. */
static int parse_emission(struct parser *ps, struct material *m, struct error *err)
{
    const char *word = read_word(ps);
    if (word == NULL)
        return 0;
    if (strcmp(word, "emit") != 0)
        return error_set(err, ps->file, ps->line, "material: unexpected '%s' (expected emit)",
                         word);
    double v[3];
    if (read_numbers(ps, v, 3, "emitted radiance r g b", err) < 0)
        return -1;
    if (!is_colour_in(v, 0, HUGE_VAL))
        return parse_error(ps, err, "emitted radiance must not be negative");
    m->emission = vec3_at(v);
    word = read_word(ps);
    if (word != NULL && strcmp(word, "twosided") == 0)
        m->two_sided = 1;
    else if (word != NULL)
        ps->next--; /* not ours: expect_end() reports it */
    return 0;
}

/* "material NAME KIND PARAMETERS [emit R G B [twosided]]" */
int parse_material(struct parser *ps, struct error *err)
{
    struct material m;
    memset(&m, 0, sizeof m);
    const char *name = read_word(ps);
    if (name == NULL)
        return parse_error(ps, err, "expected a name");
    if (strlen(name) >= MATERIAL_NAME_MAX)
        return parse_error(ps, err, "name is too long");
    if (scene_find_material(ps->scene, name) >= 0)
        return error_set(err, ps->file, ps->line, "material: '%s' is already defined", name);
    strcpy(m.name, name);
    if (parse_material_kind(ps, &m, err) < 0)
        return -1;
    if (parse_emission(ps, &m, err) < 0)
        return -1;
    if (scene_add_material(ps->scene, &m) < 0)
        return parse_error(ps, err, "too many materials");
    return expect_end(ps, err);
}

