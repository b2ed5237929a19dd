/* app/export_mitsuba.c -- placeholder until the writer lands. */
#include "export.h"

int export_mitsuba(FILE *f, const struct export_scene *es, struct error *err)
{
    (void)f;
    (void)es;
    return error_set(err, "", 0, "export: mitsuba: not written yet");
}
