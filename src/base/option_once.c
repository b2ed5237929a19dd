/*
 * base/option_once.c -- refusing an option given twice (option_once.h).
 */
#include "option_once.h"

#include <string.h>

int option_once(struct option_once *once, const char *command, const char *name,
                struct error *err)
{
    for (int k = 0; k < once->n; k++)
        if (strcmp(once->seen[k], name) == 0)
            return error_set(err, "", 0, "%s: %s is given twice: it takes one value, and a "
                             "second would silently replace the first", command, name);
    if (once->n < OPTION_ONCE_MAX)
        once->seen[once->n++] = name;
    return 0;
}
